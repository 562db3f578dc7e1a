// HSVA .dat import: the header's maneuver kept in UTF-8, units to SI and rpm, earth-fixed
// velocities to body axes, bad input located; on the nine shared zig-zags the columns are what
// the README says (r is the heading's rate, roll is small, the velocities the positions' rates).
#include "importers/hsva_dat.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.h"
#include "importers/froude_scaling.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

constexpr double kDeg = std::numbers::pi / 180.0;

// A file as HSVA writes it: four cp1252 header lines (0xB0 the degree sign), then the rows.
std::string HsvaText(const std::vector<std::string>& rows,
                     const std::string& maneuver = " Z20\xB0/10\xB0 starting to starboard") {
  std::string text =
      " HSVA, experimental data CPMC\n KVLCC2\n" + maneuver + "\n Time series of motions\n";
  for (const std::string& row : rows) text += row + "\n";
  return text;
}

const std::vector<std::string> kRows = {
    "  .000  1.0  2.0  90.0  .0  1.2  1.0  .5  -10.0  10.0  40.0  1.1",
    "  .050  1.0  2.06  90.0  .0  1.2  1.0  .5  -10.0  10.0  40.0  1.1",
    "  .100  1.0  2.12  90.0  .0  1.2  1.0  .5  -10.0  10.0  40.0  1.1"};

class HsvaDatTest : public ::testing::Test {};

// A ship heading 90 deg (east) moving east at 1.2 m/s over ground has body surge 1.2, sway 0;
// degrees become radians, rps become rpm, the maneuver line is kept in UTF-8, trimmed.
TEST_F(HsvaDatTest, ConvertsUnitsRotatesVelocitiesAndKeepsTheManeuver) {
  ImportReport report;
  const Dataset d = ParseHsvaDat(HsvaText(kRows), "x.dat", report);
  ASSERT_EQ(d.rows(), 3);
  EXPECT_DOUBLE_EQ(d.t()(1), 0.05);
  EXPECT_DOUBLE_EQ(d["north"](0), 1.0);
  EXPECT_DOUBLE_EQ(d["east"](2), 2.12);
  EXPECT_NEAR(d["psi"](0), 90 * kDeg, 1e-12);
  EXPECT_NEAR(d["u"](0), 1.2, 1e-12);
  EXPECT_NEAR(d["v"](0), 0.0, 1e-12);
  EXPECT_NEAR(d["r"](0), 1 * kDeg, 1e-12);
  EXPECT_NEAR(d["phi"](0), 0.5 * kDeg, 1e-12);
  EXPECT_NEAR(d["delta"](0), -10 * kDeg, 1e-12);  // as logged: negative to starboard
  EXPECT_DOUBLE_EQ(d["rev"](0), 600.0);
  EXPECT_DOUBLE_EQ(d["thrust"](0), 40.0);
  EXPECT_DOUBLE_EQ(d["torque"](0), 1.1);
  EXPECT_EQ(d.metadata().at("maneuver"), "Z20\xC2\xB0/10\xC2\xB0 starting to starboard");
  EXPECT_EQ(d.metadata().at("format"), "hsva-dat");
  EXPECT_EQ(d.Source(), "x.dat");
  EXPECT_THAT(report.notes, ::testing::Contains(HasSubstr("maneuver 'Z20\xC2\xB0/10\xC2\xB0")));
  // CRLF line ends and blank lines change nothing.
  std::string crlf;
  for (char c : HsvaText(kRows) + "\n") crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const Dataset windows = ParseHsvaDat(crlf, "x.dat", report);
  EXPECT_EQ(windows.t(), d.t());
  EXPECT_EQ(windows.metadata().at("maneuver"), d.metadata().at("maneuver"));
}

// Every channel has a Froude dimension, rev as revolutions per time: --scale needs no
// --dimension.
TEST_F(HsvaDatTest, ScalesAsAWhole) {
  ImportReport report;
  Dataset d = ParseHsvaDat(HsvaText(kRows), "x.dat", report);
  FroudeScale(d, 45.7);
  const double s = std::sqrt(45.7);
  EXPECT_NEAR(d.t()(2), 0.1 * s, 1e-12);
  EXPECT_NEAR(d["u"](0), 1.2 * s, 1e-12);
  EXPECT_NEAR(d["rev"](0), 600.0 / s, 1e-9);
  EXPECT_NEAR(d["r"](0), kDeg / s, 1e-12);
  EXPECT_NEAR(d["thrust"](0), 40.0 * std::pow(45.7, 3), 1e-6);
  EXPECT_NEAR(d["torque"](0), 1.1 * std::pow(45.7, 4), 1e-4);
  EXPECT_NEAR(d["delta"](0), -10 * kDeg, 1e-12);
}

struct BadCase {
  const char* name;
  std::string text;
  const char* starts;  // the message's start: "file:line[:column]: what"
};

class HsvaDatBadInputTest : public ::testing::TestWithParam<BadCase> {};

// Each kind of bad input is an InputError that names the line and what was wrong.
TEST_P(HsvaDatBadInputTest, IsRefusedWithItsLine) {
  const BadCase& c = GetParam();
  ImportReport report;
  try {
    ParseHsvaDat(c.text, "x.dat", report);
    FAIL() << "accepted: " << c.name;
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), StartsWith(c.starts));
  }
}

std::vector<BadCase> BadCases() {
  std::vector<std::string> short_row = kRows, text = kRows, back = kRows, repeat = kRows;
  short_row[1] = "  .050  1.0  2.06  90.0  .0  1.2  1.0  .5  -10.0  10.0  40.0";
  text[0] = "  .000  1.0  2.0  abc  .0  1.2  1.0  .5  -10.0  10.0  40.0  1.1";
  back[2] = "  .040  1.0  2.12  90.0  .0  1.2  1.0  .5  -10.0  10.0  40.0  1.1";
  repeat[2] = "  .050  1.0  2.12  90.0  .0  1.2  1.0  .5  -10.0  10.0  40.0  1.1";
  std::string nan_row = kRows[0];
  nan_row.replace(nan_row.find("40.0"), 4, "nan ");
  return {
      {"empty file", "", "x.dat: the file ends after 0 lines"},
      {"three lines", " HSVA\n KVLCC2\n Z20\xB0/10\xB0\n", "x.dat:3: the file ends after 3 lines"},
      {"header line missing", " HSVA\n KVLCC2\n Z20\xB0/10\xB0\n" + kRows[0] + "\n",
       "x.dat:4:1: a row of numbers where header line 4 (title) belongs"},
      {"no header", kRows[0] + "\n" + kRows[1] + "\n",
       "x.dat:1:1: a row of numbers where header line 1 (institute) belongs"},
      {"empty maneuver", HsvaText(kRows, "  \t "), "x.dat:3: header line 3 (the maneuver"},
      {"undefined cp1252 byte", HsvaText(kRows, " Z20\x81/10"),
       "x.dat:3:5: byte 0x81 is not cp1252 text"},
      {"control byte", HsvaText(kRows, " Z20\x01"), "x.dat:3:5: byte 0x01 is not cp1252 text"},
      {"no rows", HsvaText({}), "x.dat:4: no data rows"},
      {"short row", HsvaText(short_row), "x.dat:6:61: expected 12 columns, found 11"},
      {"text", HsvaText(text), "x.dat:5:19: column 'psi': 'abc' is not a number"},
      {"nan", HsvaText({nan_row}), "x.dat:5:56: column 'thrust'"},
      {"time back", HsvaText(back), "x.dat:7:3: time 0.04 goes back from the previous 0.05"},
      {"time repeats", HsvaText(repeat), "x.dat:7:3: time 0.05 repeats the previous 0.05"},
      {"cp1252 in a row", HsvaText({kRows[0] + " \xB0"}), "x.dat:5:"},
  };
}

INSTANTIATE_TEST_SUITE_P(Cases, HsvaDatBadInputTest, ::testing::ValuesIn(BadCases()),
                         [](const auto& info) {
                           std::string name = info.param.name;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

double Correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const Eigen::ArrayXd x = a.array() - a.mean(), y = b.array() - b.mean();
  return (x * y).sum() / std::sqrt((x * x).sum() * (y * y).sum());
}

// Central differences of x over t, rows 1 .. n-2.
Eigen::VectorXd Rate(const Eigen::VectorXd& x, const Eigen::VectorXd& t) {
  const Eigen::Index n = x.size() - 2;
  return ((x.tail(n) - x.head(n)).array() / (t.tail(n) - t.head(n)).array()).matrix();
}

struct SharedRun {
  const char* file;
  const char* maneuver;  // header line 3 in UTF-8, trimmed
  double duration_s;
};

class HsvaDatSharedTest : public ::testing::TestWithParam<SharedRun> {};

// Each shared zig-zag imports with its header's maneuver, at 20 Hz from t = 0; the columns are
// what the README says: r is the heading's rate in deg/s (correlation > 0.99, slope 1), the
// earth-fixed velocities are the positions' rates, roll stays below 1 deg, the first row's body
// surge is the speed over ground (1.178 m/s, heading about 0), the propeller runs at 10.23 rps,
// and a negative rudder turns the ship to starboard (psi grows), as in MARIN's files.
TEST_P(HsvaDatSharedTest, ImportsWithTheColumnsTheReadmeSays) {
  const SharedRun& run = GetParam();
  const std::string path = std::string(USVID_SHARED_DATA_DIR) + "/kvlcc2-hsva/" + run.file;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared data absent: " << path;
  ImportReport report;
  const Dataset d = ImportHsvaDat(path, report);
  EXPECT_EQ(d.metadata().at("maneuver"), run.maneuver);
  const Eigen::VectorXd& t = d.t();
  EXPECT_EQ(d.rows(), std::lround(run.duration_s * 20) + 1);
  EXPECT_EQ(t(0), 0.0);
  EXPECT_NEAR(d.duration(), run.duration_s, 1e-9);
  const Eigen::Index n = d.rows() - 2;

  const Eigen::VectorXd psi_rate = Rate(d["psi"], t), r = d["r"].segment(1, n);
  EXPECT_GT(Correlation(r, psi_rate), 0.99);
  EXPECT_NEAR(r.dot(psi_rate) / psi_rate.squaredNorm(), 1.0, 0.02);  // deg/s, as psi's deg

  const Eigen::ArrayXd c = d["psi"].array().cos(), s = d["psi"].array().sin();
  const Eigen::VectorXd vn = (d["u"].array() * c - d["v"].array() * s).matrix();
  const Eigen::VectorXd ve = (d["u"].array() * s + d["v"].array() * c).matrix();
  EXPECT_LT((Rate(d["north"], t) - vn.segment(1, n)).cwiseAbs().mean(), 0.001);
  EXPECT_LT((Rate(d["east"], t) - ve.segment(1, n)).cwiseAbs().mean(), 0.001);

  EXPECT_LT(d["phi"].cwiseAbs().maxCoeff(), 1 * kDeg);
  EXPECT_LT(std::abs(d["psi"](0)), 0.1 * kDeg);
  EXPECT_NEAR(d["u"](0), std::hypot(vn(0), ve(0)), 1e-3);
  EXPECT_NEAR(d["u"](0), 1.178, 0.004);
  EXPECT_LT(std::abs(d["v"](0)), 0.005);
  EXPECT_NEAR(d["rev"](0), 10.2295 * 60, 1e-9);

  Eigen::Index first = 0;  // the first helm order
  while (std::abs(d["delta"](first)) < 5 * kDeg) ++first;
  const Eigen::Index later = first + 200;  // 10 s on
  ASSERT_LT(later, d.rows());
  EXPECT_LT(d["delta"](first) * (d["psi"](later) - d["psi"](first)), 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    Kvlcc2Hsva, HsvaDatSharedTest,
    ::testing::Values(SharedRun{"HSVA_CPMC_KVLCC2_Z_10_01.dat", "Z10\xC2\xB0/1\xC2\xB0", 165.0},
                      SharedRun{"HSVA_CPMC_KVLCC2_Z_10_05.dat", "Z10\xC2\xB0/5\xC2\xB0", 175.0},
                      SharedRun{"HSVA_CPMC_KVLCC2_Z_10_10_P.dat",
                                "Z10\xC2\xB0/10\xC2\xB0 starting to port", 66.0},
                      SharedRun{"HSVA_CPMC_KVLCC2_Z_15_01.dat", "Z15\xC2\xB0/1\xC2\xB0", 165.0},
                      SharedRun{"HSVA_CPMC_KVLCC2_Z_15_05.dat", "Z15\xC2\xB0/5\xC2\xB0", 185.0},
                      SharedRun{"HSVA_CPMC_KVLCC2_Z_20_05.dat", "Z20\xC2\xB0/5\xC2\xB0", 177.0},
                      SharedRun{"HSVA_CPMC_KVLCC2_Z_20_10_S.dat",
                                "Z20\xC2\xB0/10\xC2\xB0 starting to starboard", 190.0},
                      SharedRun{"HSVA_CPMC_KVLCC2_Z_25_05.dat", "Z25\xC2\xB0/5\xC2\xB0", 185.0},
                      SharedRun{"HSVA_CPMC_KVLCC2_Z_30_05.dat", "Z30\xC2\xB0/5\xC2\xB0", 200.0}),
    [](const auto& info) {
      std::string name = info.param.file;
      name = name.substr(std::string("HSVA_CPMC_KVLCC2_").size());
      return name.substr(0, name.find('.'));
    });

}  // namespace
}  // namespace usvid
