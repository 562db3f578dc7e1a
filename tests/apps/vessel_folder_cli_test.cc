// Vessel folders as a user meets them (issue 72): `usvid compare --suite real --data-dir DIR`
// runs every DIR/NAME with a track.yaml, cross-validated over its runs unless the track splits
// them; a bad track.yaml is exit 2 naming its line and key with nothing written; a folder without
// runs is skipped with a message; `usvid init-track` starts a folder from a log's header.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using testing::RunUsvid;
using testing::WriteText;
namespace fs = std::filesystem;

nlohmann::json ReadJson(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

class VesselFolderCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = FreshTempDir();
    // A tanker's trials: three simulated runs of kvlcc2, in the subfolders a user keeps them in.
    fs::create_directories(dir_ / "trials" / "tanker" / "zigzag");
    fs::create_directories(dir_ / "trials" / "tanker" / "turning");
    for (const auto& [file, maneuver, seconds] :
         {std::tuple{"zigzag/zz1.csv", "zigzag:20/20", 400},
          std::tuple{"zigzag/zz2.csv", "zigzag:-20/20", 401},
          std::tuple{"turning/tc.csv", "turning:35", 600}})
      ASSERT_EQ(
          RunUsvid("simulate --vessel kvlcc2 --maneuver " + std::string(maneuver) + " --duration " +
                   std::to_string(seconds) + " --noise 0.005 --seed " + std::to_string(seconds) +
                   " --out " + (dir_ / "trials" / "tanker" / file).string())
              .exit_code,
          0);
  }
  testing::RunResult Compare() {
    return RunUsvid("compare --suite real --data-dir " + (dir_ / "trials").string() +
                    " --threads 2 --out " + (dir_ / "out").string());
  }
  fs::path dir_;
};

TEST_F(VesselFolderCliTest, AFolderWithoutASplitIsCrossValidatedOverItsRuns) {
  WriteText(dir_ / "trials" / "tanker" / "track.yaml",
            "vessel: kvlcc2\nformat: csv\nmethods: [nomoto]\n");
  fs::create_directories(dir_ / "trials" / "empty");
  WriteText(dir_ / "trials" / "empty" / "track.yaml", "format: csv\n");
  const auto r = Compare();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("3 runs, each held out in turn"));
  EXPECT_THAT(r.err, HasSubstr("vessel folder skipped: empty"));
  const nlohmann::json results = ReadJson(dir_ / "out" / "tanker" / "results.json");
  ASSERT_EQ(results["rows"].size(), 3u);  // nomoto scored once on each run it did not see
  std::set<std::string> scored;
  for (const nlohmann::json& row : results["rows"]) {
    EXPECT_EQ(row["status"], "ok") << row.dump();
    scored.insert(row["test_maneuver"].get<std::string>());
  }
  EXPECT_EQ(scored, (std::set<std::string>{"zz1", "zz2", "tc"}));
  // The zig-zags and the circle are re-run closed-loop as their records say.
  int replayed = 0;
  for (const nlohmann::json& row : results["rows"]) replayed += row.contains("closed_loop");
  EXPECT_EQ(replayed, 3);
}

TEST_F(VesselFolderCliTest, ASplitTrainsOnItsRunsAndScoresTheRest) {
  WriteText(dir_ / "trials" / "tanker" / "track.yaml",
            "vessel: kvlcc2\nformat: csv\nmethods: [nomoto, lti]\n"
            "split:\n  train: [zigzag/zz1.csv, turning/tc.csv]\n"
            "  test: [{file: zigzag/zz2.csv, name: zigzag -20}]\n");
  const auto r = Compare();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json results = ReadJson(dir_ / "out" / "tanker" / "results.json");
  ASSERT_EQ(results["rows"].size(), 2u);
  for (const nlohmann::json& row : results["rows"]) {
    EXPECT_EQ(row["train_maneuver"], "2 runs");
    EXPECT_EQ(row["test_maneuver"], "zigzag -20");
  }
}

TEST_F(VesselFolderCliTest, ABadTrackFileIsExit2AtItsLineWithNothingWritten) {
  const fs::path track = dir_ / "trials" / "tanker" / "track.yaml";
  const auto refused = [&](const std::string& text, const std::string& what) {
    WriteText(track, text);
    const auto r = Compare();
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_THAT(r.err, HasSubstr(track.string() + what)) << text;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out")) << text;
  };
  refused("format: csv-log\ncolumns:\n  t: t\n  yawrate: r\n",
          ":4:12: columns.yawrate: unknown channel");
  refused("format: csv-log\ncolumns:\n  t: t\n  r: yaw_rate\n",
          ":4:6: columns.r: 'yaw_rate' is not a column of");
  refused("format: csv\nscale: 0\n", ":2:8: scale: must be above 0, got 0");
  refused("format: csv\nmethod: [nomoto]\n", ":2:1: method: unknown key");
  // Without a split the runs are cross-validated, which leaves out the methods that search the
  // vessel: a track of nothing else has nothing to run.
  refused("vessel: kvlcc2\nformat: csv\nmethods: [hybrid, diagnose]\n",
          ": methods: --cv leaves out diagnose and hybrid, and the track has no other method");
}

TEST(VesselFolderInitTest, InitTrackStartsAFolderFromALogsHeader) {
  const fs::path dir = FreshTempDir();
  WriteText(dir / "log.csv", "time,heading [deg],rudder,lat,lon\n0,1,2,3,4\n1,1,2,3,4\n");
  const auto r = RunUsvid("init-track " + (dir / "trials" / "boat").string() + " --data " +
                          (dir / "log.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "trials" / "boat" / "log.csv"));  // copied in
  std::ifstream in(dir / "trials" / "boat" / "track.yaml");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_THAT(text.str(), HasSubstr("  psi: \"heading [deg]:deg\"\n"));
  EXPECT_THAT(text.str(), HasSubstr("  delta: rudder\n"));
  EXPECT_THAT(text.str(), HasSubstr("#   ?: lat\n"));
  EXPECT_THAT(text.str(), HasSubstr("rate_from: psi"));
  // Run again, it keeps the user's file.
  const auto again = RunUsvid("init-track " + (dir / "trials" / "boat").string() + " --data " +
                              (dir / "log.csv").string());
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_THAT(again.err, HasSubstr("track.yaml: already there (--force writes over it)"));
}

}  // namespace
}  // namespace usvid
