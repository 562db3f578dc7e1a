// A vessel folder's track.yaml (harness/track_file.h) and the first one usvid init-track writes
// (harness/track_init.h): what a user writes becomes the suite's read keys, and every mistake
// names track.yaml's line and the key (issue 72).
#include "harness/track_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "harness/track_init.h"
#include "importers/csv_log.h"

namespace usvid {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class TrackFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("usvid_track_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "zigzag");
    Write(dir_ / "zigzag" / "a.csv", "time,heading [deg],rudder,x0,y0\n0,1,2,3,4\n");
    Write(dir_ / "zigzag" / "b.csv", "time,heading [deg],rudder,x0,y0\n0,1,2,3,4\n");
  }
  void TearDown() override { fs::remove_all(dir_); }
  static void Write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }
  std::string Track(const std::string& text) {
    Write(dir_ / "track.yaml", text);
    return (dir_ / "track.yaml").string();
  }
  // The message ReadTrackFile (and CheckColumnsOf, on `run`) gives, or "" when it reads.
  std::string ErrorOf(const std::string& text, const std::string& run = "") {
    try {
      const TrackFile t = ReadTrackFile(Track(text));
      if (!run.empty()) CheckColumnsOf(t, (dir_ / run).string());
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(TrackFileTest, ATrackFileBecomesTheSuitesReadKeys) {
  const TrackFile t = ReadTrackFile(
      Track("name: my-usv\n"
            "format: csv-log\n"
            "columns:\n"
            "  t: time\n"
            "  psi: heading [deg]:deg\n"
            "  delta: rudder\n"
            "rate_from: psi\n"
            "scale: 2.5\n"
            "runs:\n"
            "  zigzag: zigzag\n"
            "split:\n"
            "  train: [zigzag/a.csv]\n"
            "  test:\n"
            "    - {file: zigzag/b.csv, maneuver: 'zigzag:20/20', name: the other}\n"
            "methods: [sindy, {method: gp, population: 300, base: vessel, inputs: [n, delta],\n"
            "          rudder_inflow: true, operators: '+,-'}]\n"));
  EXPECT_EQ(t.name, "my-usv");
  EXPECT_EQ(t.vessel, "");  // no vessel.yaml beside it
  EXPECT_EQ(t.read["map"], "t=time,psi=heading [deg]:deg,delta=rudder");
  EXPECT_EQ(t.read["rate_from"], "psi");
  EXPECT_EQ(t.read["scale"], 2.5);
  ASSERT_EQ(t.folders.size(), 1u);
  EXPECT_EQ(t.folders[0].tests, "zigzag");
  ASSERT_EQ(t.train.size(), 1u);
  EXPECT_EQ(t.train[0]["file"], "zigzag/a.csv");
  EXPECT_EQ(t.train[0]["name"], "a");
  EXPECT_EQ(t.test[0]["maneuver"], "zigzag:20/20");
  EXPECT_EQ(t.test[0]["name"], "the other");
  EXPECT_EQ(t.methods[1]["population"], 300);  // a number, as a suite file gives it
  EXPECT_EQ(t.methods[1]["base"], "vessel");
  EXPECT_EQ(t.methods[1]["inputs"], (nlohmann::json{"n", "delta"}));  // n, not YAML 1.1's false
  EXPECT_EQ(t.methods[1]["rudder_inflow"], true);
  EXPECT_EQ(t.methods[1]["operators"], "+,-");
}

TEST_F(TrackFileTest, WithoutMethodsTheDataDrivenOnesRunAndTheVesselsWithAVessel) {
  const TrackFile none = ReadTrackFile(Track("columns: {t: time, delta: rudder}\n"));
  EXPECT_EQ(none.methods, (nlohmann::json{"sindy", "gp"}));  // no r for Nomoto's model
  EXPECT_EQ(none.name, dir_.filename().string());
  const TrackFile rate =
      ReadTrackFile(Track("columns: {t: time, delta: rudder}\nrate_from: psi\n"));
  EXPECT_EQ(rate.methods[0]["method"], "nomoto");
  EXPECT_EQ(rate.methods[0]["inputs"], (nlohmann::json{"delta"}));
  Write(dir_ / "vessel.yaml", "name: x\n");
  const TrackFile with = ReadTrackFile(Track("columns: {t: time}\n"));
  EXPECT_EQ(with.vessel, (dir_ / "vessel.yaml").string());
  EXPECT_EQ(with.methods[0], "nominal");
  EXPECT_EQ(with.methods.back()["base"], "vessel");  // grey-box GP
}

TEST_F(TrackFileTest, MistakesNameTheLineAndTheKey) {
  const std::string file = (dir_ / "track.yaml").string();
  EXPECT_THAT(ErrorOf("columns: {t: time}\nformats: csv\n"),
              HasSubstr(file + ":2:1: formats: unknown key"));
  EXPECT_THAT(ErrorOf("columns:\n  t: time\n  heading: heading\n"),
              HasSubstr(file + ":3:12: columns.heading: unknown channel (known:"));
  EXPECT_THAT(ErrorOf("columns: {t: time}\nscale: 0\n"),
              HasSubstr(file + ":2:8: scale: must be above 0, got 0"));
  EXPECT_THAT(ErrorOf("columns: {psi: heading}\n"), HasSubstr("t: missing"));
  EXPECT_THAT(ErrorOf("columns:\n  t: time\n  u: speed:furlongs\n"),
              HasSubstr(file + ":3:6: columns.u: --map 'u=speed:furlongs': unknown unit"));
  EXPECT_THAT(ErrorOf("columns: {t: time}\nruns: {zigzag: zig}\n"),
              HasSubstr(file + ":2:16: runs.zigzag: the tests its runs hold"));
  EXPECT_THAT(ErrorOf("columns: {t: time}\nsplit: {train: [nope.csv], test: [zigzag/a.csv]}\n"),
              HasSubstr("train: nope.csv: no such run"));
  EXPECT_THAT(ErrorOf("format: marin-dat\ncolumns: {t: time}\n"),
              HasSubstr(file + ":2:10: columns: format marin-dat names its own columns"));
}

TEST_F(TrackFileTest, AMapToAColumnTheLogLacksNamesItsLineAndTheRun) {
  EXPECT_EQ(ErrorOf("columns:\n  t: time\n  delta: rudder\n", "zigzag/a.csv"), "");
  EXPECT_THAT(ErrorOf("columns:\n  t: time\n  delta: rudder_angle\n", "zigzag/a.csv"),
              HasSubstr((dir_ / "track.yaml").string() +
                        ":3:10: columns.delta: 'rudder_angle' "
                        "is not a column of " +
                        (dir_ / "zigzag" / "a.csv").string()));
}

TEST(TrackInitTest, RecognisesTheSharedLogsColumns) {
  // Esso Osaka's pond log and the small USV's GPS log (../shared/data), their headers as given.
  const RecognisedColumns esso = RecogniseColumns(
      {"t [s]", "x_position_mid [m]", "u_velo [m/s]", "y_position_mid [m]", "vm_velo [m/s]",
       "psi_hat [rad]", "r_angvelo [rad/s]", "n_prop [rps]", "delta_rudder [rad]",
       "wind_velo_relative_mid [m/s]", "wind_dir_relative_mid [rad]", "wind_velo_true [m/s]",
       "wind_dir_true [rad]"});
  using Pairs = std::vector<std::pair<std::string, std::string>>;
  EXPECT_EQ(esso.mapped, (Pairs{{"t", "t [s]"},
                                {"north", "x_position_mid [m]"},
                                {"east", "y_position_mid [m]"},
                                {"psi", "psi_hat [rad]"},
                                {"u", "u_velo [m/s]"},
                                {"v", "vm_velo [m/s]"},
                                {"r", "r_angvelo [rad/s]"},
                                {"delta", "delta_rudder [rad]"},
                                {"n", "n_prop [rps]"},
                                {"wind_speed", "wind_velo_relative_mid [m/s]"},
                                {"wind_direction", "wind_dir_relative_mid [rad]"}}));
  EXPECT_EQ(esso.unmapped,
            (std::vector<std::string>{"wind_velo_true [m/s]", "wind_dir_true [rad]"}));
  const RecognisedColumns usv = RecogniseColumns(
      {"time", "lon", "lat", "speed", "heading", "xcourse", "ycourse", "zcourse", "rudder_command",
       "rudder", "delta", "psi", "thrust", "-rudder", "x0", "y0"});
  EXPECT_EQ(usv.mapped, (Pairs{{"t", "time"},
                               {"north", "x0"},
                               {"east", "y0"},
                               {"psi", "psi"},
                               {"U", "speed"},
                               {"delta", "delta"}}));
  // A heading in degrees says so in its map.
  EXPECT_EQ(RecogniseColumns({"Time", "Heading (deg)"}).mapped,
            (Pairs{{"t", "Time"}, {"psi", "Heading (deg):deg"}}));
}

TEST_F(TrackFileTest, TheFirstTrackFileReadsBackWithRFromTheHeading) {
  const std::string text = TrackFileText(
      "usv", RecogniseColumns(CsvLogColumns((dir_ / "zigzag" / "a.csv").string())), "a.csv", false);
  const TrackFile t = ReadTrackFile(Track(text));
  EXPECT_EQ(t.read["map"], "t=time,north=x0,east=y0,psi=heading [deg]:deg,delta=rudder");
  EXPECT_EQ(t.read["rate_from"], "psi");
  EXPECT_FALSE(t.split);
  EXPECT_THAT(text, HasSubstr("No vessel.yaml"));
}

}  // namespace
}  // namespace usvid
