// Foreign CSV logs: column maps with units, separators, earth-to-body, time repair.
#include "importers/csv_log.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/error.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;

class CsvLogTest : public ::testing::Test {
 protected:
  static Dataset Parse(const std::string& text, const std::vector<std::string>& map,
                       ImportReport* report = nullptr) {
    ImportReport local;
    return ParseCsvLog(text, "log.csv", ParseColumnMap(map), report ? *report : local);
  }
};

// Units convert to SI: degrees, knots, rpm; unmapped text columns are left alone.
TEST_F(CsvLogTest, MapsColumnsWithUnits) {
  const Dataset d = Parse("stamp;date;hdg;sog;jet\n0;2024-05-01;90;10;600\n0.5;2024-05-01;45;2;0\n",
                          {"t=stamp", "psi=hdg:deg", "U=sog:knots", "n=jet:rpm"});
  EXPECT_NEAR(d["psi"](0), std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(d["U"](0), 5.144444, 1e-6);
  EXPECT_NEAR(d["n"](0), 20 * std::numbers::pi, 1e-9);
  EXPECT_FALSE(d.Has("date"));
}

// Earth-fixed velocities become body-fixed surge and sway.
TEST_F(CsvLogTest, RotatesEarthVelocitiesToBody) {
  const Dataset d =
      Parse("t,vn,ve,psi\n0,0,3,90\n1,3,0,0\n", {"t=t", "vn=vn", "ve=ve", "psi=psi:deg"});
  EXPECT_NEAR(d["u"](0), 3.0, 1e-12);
  EXPECT_NEAR(d["v"](0), 0.0, 1e-12);
  EXPECT_NEAR(d["u"](1), 3.0, 1e-12);
}

// Repeated and decreasing stamps are dropped and the count reported, never silently.
TEST_F(CsvLogTest, RepairsTimeAndSaysSo) {
  ImportReport report;
  const Dataset d = Parse("time,x\n0,1\n1,2\n1,3\n0.5,4\n2,5\n", {"t=time", "x=x"}, &report);
  EXPECT_EQ(d.rows(), 3);
  EXPECT_THAT(report.notes, ::testing::Contains(HasSubstr("dropping 2 rows")));
}

// Errors name the file, line and column, or the map item at fault.
TEST_F(CsvLogTest, BadInputIsLocated) {
  try {
    Parse("time,x\n0,1\n1,oops\n", {"t=time", "x=x"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::StartsWith("log.csv:3:3: column 'x'"));
  }
  EXPECT_THROW(Parse("time,x\n0,1\n", {"t=time", "x=nope"}), InputError);
  EXPECT_THROW(Parse("time,x\n0,1\n", {"x=x"}), InputError);
  EXPECT_THROW(ParseColumnMap({"u=speed:furlongs"}), InputError);
  EXPECT_THROW(ParseColumnMap({"u"}), InputError);
  EXPECT_THROW(ParseColumnMap({"u=a", "u=b"}), InputError);
}

// The small USV's GPS log imports with a map (issue 2 acceptance).
TEST_F(CsvLogTest, RealFuzhouUsvLogImportsWithMap) {
  const std::string path =
      std::string(USVID_SHARED_DATA_DIR) + "/usv-fuzhou/zigzag_30_inter_xy.csv";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared data absent: " << path;
  ImportReport report;
  const Dataset d = ImportCsvLog(path,
                                 ParseColumnMap({"t=time", "north=x0", "east=y0", "psi=psi",
                                                 "U=speed", "delta=delta", "heading=heading:deg"}),
                                 report);
  EXPECT_EQ(d.rows(), 420);
  EXPECT_NEAR(d.duration(), 209.5, 1e-9);
  // The log's heading [deg] and psi [rad] are the same angle.
  EXPECT_LT((d["heading"] - d["psi"]).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT(d["delta"].cwiseAbs().maxCoeff(), 0.6);
}

}  // namespace
}  // namespace usvid
