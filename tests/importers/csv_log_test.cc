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

// Rows with every cell empty (a logger's padding) are dropped and said; a row with one empty
// cell is still an unsampled value, and an empty time still an error.
TEST_F(CsvLogTest, DropsRowsWithEveryCellEmpty) {
  ImportReport report;
  const Dataset d =
      Parse("time,x,y\n0,1,2\n1,,3\n2,5,6\n,,\n , ,\n", {"t=time", "x=x", "y=y"}, &report);
  EXPECT_EQ(d.rows(), 3);
  EXPECT_FALSE(d.Get("x").IsSampled(1));
  EXPECT_THAT(
      report.notes,
      ::testing::Contains(HasSubstr("dropped 2 rows with every cell empty (the first at line 5)")));
  EXPECT_THROW(Parse("time,x\n0,1\n,2\n", {"t=time", "x=x"}), InputError);
  EXPECT_THROW(Parse("time,x\n0,1\n,\n", {"t=time", "x=x"}), InputError);  // one row left
}

// A heading logged within one turn (-180..180 deg) runs on through the wrap when the vessel
// turns a circle, and the import says how many jumps it removed; a heading that never wraps is
// left as it is.
TEST_F(CsvLogTest, UnwrapsAHeadingLoggedWithinOneTurnAndSaysSo) {
  ImportReport report;
  const Dataset d =
      Parse("t,hdg\n0,170\n1,-170\n2,-150\n3,\n4,170\n5,-175\n", {"t=t", "psi=hdg:deg"}, &report);
  const double deg = std::numbers::pi / 180.0;
  EXPECT_NEAR(d["psi"](1), 190 * deg, 1e-12);
  EXPECT_NEAR(d["psi"](2), 210 * deg, 1e-12);
  EXPECT_FALSE(d.Get("psi").IsSampled(3));
  EXPECT_NEAR(d["psi"](4), 170 * deg, 1e-12);  // turned back through the wrap
  EXPECT_NEAR(d["psi"](5), 185 * deg, 1e-12);
  EXPECT_THAT(report.notes, ::testing::Contains(HasSubstr("psi: unwrapped 3 jumps of 2 pi")));
  ImportReport quiet;
  const Dataset calm = Parse("t,hdg\n0,10\n1,-10\n", {"t=t", "psi=hdg:deg"}, &quiet);
  EXPECT_NEAR(calm["psi"](1), -10 * deg, 1e-12);
  EXPECT_THAT(quiet.notes, ::testing::Not(::testing::Contains(HasSubstr("unwrapped"))));
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

// The Esso Osaka zig-zag that ends in 327 empty rows imports with a column map alone (issue 38;
// docs/real-data.md#esso-osaka gives the map).
TEST_F(CsvLogTest, RealEssoOsakaZigZagImportsWithMapAlone) {
  const std::string path =
      std::string(USVID_SHARED_DATA_DIR) + "/esso-osaka/zigzag/zigzag_31-Jul-2020_13_50_28.csv";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared data absent: " << path;
  ImportReport report;
  const Dataset d = ImportCsvLog(
      path,
      ParseColumnMap({"t=t [s]", "x=x_position_mid [m]", "y=y_position_mid [m]",
                      "psi=psi_hat [rad]", "u=u_velo [m/s]", "v=vm_velo [m/s]",
                      "r=r_angvelo [rad/s]", "n=n_prop [rps]", "delta=delta_rudder [rad]",
                      "wind_speed=wind_velo_relative_mid [m/s]",
                      "wind_direction=wind_dir_relative_mid [rad]"}),
      report);
  EXPECT_THAT(report.notes,
              ::testing::Contains(HasSubstr("dropped 327 rows with every cell empty")));
  EXPECT_GT(d.rows(), 1000);
  EXPECT_TRUE(d.Get("u").FullySampled());
  EXPECT_LT(d["delta"].cwiseAbs().maxCoeff(), 0.7);  // radians already
}

}  // namespace
}  // namespace usvid
