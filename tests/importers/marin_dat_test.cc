// MARIN .dat import: units, earth-to-body velocities, repeated stamps repaired and reported.
#include "importers/marin_dat.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/error.h"

namespace usvid {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

class MarinDatTest : public ::testing::Test {};

// A ship heading 90 deg (east) moving east at 5 m/s has body surge 5, sway 0; degrees become
// radians; the repeated stamp is rebuilt onto the grid and reported.
TEST_F(MarinDatTest, ConvertsUnitsAndRotatesVelocities) {
  const std::string text =
      "MARIN\nZig-zag\n\n"
      "0.00E+00\t0\t0\t0\t9.00E+01\t0\t5.00E+00\t0\t1.00E+00\t2.00E+01\t9.17E+01\n\n"
      "1.35E-01\t0\t0.675\t0\t9.00E+01\t0\t5.00E+00\t0\t1.00E+00\t2.00E+01\t9.17E+01\n"
      "2.71E-01\t0\t1.35\t0\t9.00E+01\t0\t5.00E+00\t0\t1.00E+00\t2.00E+01\t9.17E+01\n"
      "2.71E-01\t0\t2.03\t0\t9.00E+01\t0\t5.00E+00\t0\t1.00E+00\t2.00E+01\t9.17E+01\n";
  ImportReport report;
  const Dataset d = ParseMarinDat(text, "x.dat", report);
  ASSERT_EQ(d.rows(), 4);
  EXPECT_NEAR(d["u"](0), 5.0, 1e-12);
  EXPECT_NEAR(d["v"](0), 0.0, 1e-12);
  EXPECT_NEAR(d["psi"](0), 90 * kDeg, 1e-12);
  EXPECT_NEAR(d["r"](0), 1 * kDeg, 1e-12);
  EXPECT_NEAR(d["delta"](0), 20 * kDeg, 1e-12);
  EXPECT_DOUBLE_EQ(d["rev"](0), 91.7);
  EXPECT_GT(d.t()(3), d.t()(2));
  EXPECT_THAT(report.notes, ::testing::Contains(::testing::HasSubstr("1 repeated")));
}

// A row with a missing column is located.
TEST_F(MarinDatTest, ShortRowIsLocated) {
  ImportReport report;
  EXPECT_THROW(
      {
        try {
          ParseMarinDat("a\nb\n\n0 1 2 3\n", "x.dat", report);
        } catch (const InputError& e) {
          EXPECT_THAT(e.what(), ::testing::StartsWith("x.dat:4:8: expected 11 columns"));
          throw;
        }
      },
      InputError);
}

// The real KVLCC2 20/20 zig-zag (issue 2 acceptance): t strictly increasing, body u about
// 8.1 m/s at t = 0, |v| < 2 m/s throughout, angles in radians, repaired rows reported.
TEST_F(MarinDatTest, RealKvlcc2ZigZagImports) {
  const std::string path =
      std::string(USVID_SHARED_DATA_DIR) + "/kvlcc2-marin/MARIN_FREE_KVLCC2_zz_20_m.dat";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared data absent: " << path;
  ImportReport report;
  const Dataset d = ImportMarinDat(path, report);
  EXPECT_EQ(d.rows(), 4481);
  for (Eigen::Index i = 1; i < d.rows(); ++i) ASSERT_GT(d.t()(i), d.t()(i - 1)) << i;
  EXPECT_NEAR(d["u"](0), 8.1, 0.05);
  EXPECT_LT(d["v"].cwiseAbs().maxCoeff(), 2.0);
  EXPECT_LT(d["psi"].cwiseAbs().maxCoeff(), 40 * kDeg);
  EXPECT_NEAR(d["delta"].maxCoeff(), 20 * kDeg, 1 * kDeg);
  EXPECT_NEAR(d.duration(), 606.0, 1.0);
  EXPECT_THAT(report.notes, ::testing::Contains(::testing::HasSubstr("repaired 3235 rows")));
}

}  // namespace
}  // namespace usvid
