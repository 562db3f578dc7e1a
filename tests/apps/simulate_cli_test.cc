// `usvid simulate` as a user runs it: data and F.truth.json written, seeded and reproducible,
// multi-rate sensors as empty cells, and bad input refused with exit code 2 and no output.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "core/csv_dataset.h"
#include "core/csv_tokenizer.h"
#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using testing::RunUsvid;
namespace fs = std::filesystem;

class SimulateCliTest : public ::testing::Test {};

// A zig-zag writes the vessel's channels and a truth file with the vessel, parameters,
// effects, seed and the overshoot angles.
TEST_F(SimulateCliTest, ZigZagWritesDataAndTruth) {
  const auto dir = FreshTempDir();
  const auto out = (dir / "zz.csv").string();
  const auto r = RunUsvid(
      "simulate --vessel odin3dof --maneuver zigzag:20/20 --noise 0.01 "
      "--seed 4 --effect current=0.3 --out " +
      out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Dataset d = ReadDatasetCsv(out);
  for (const char* c : {"north", "east", "psi", "u", "v", "r", "tau_x", "tau_y", "tau_n"})
    EXPECT_TRUE(d.Has(c)) << c;
  EXPECT_NEAR(d.duration(), 300.0, 1e-9);
  const nlohmann::json truth = ReadJsonFile((dir / "zz.truth.json").string());
  EXPECT_EQ(truth.at("vessel"), "odin3dof");
  EXPECT_EQ(truth.at("seed"), 4);
  EXPECT_EQ(truth.at("parameters").at("m33"), 20928.0);
  EXPECT_EQ(truth.at("effects").at(0).at("effect"), "current");
  EXPECT_TRUE(truth.at("maneuver").at("report").contains("first_overshoot_deg"));
  EXPECT_TRUE(truth.at("maneuver").at("report").contains("second_overshoot_deg"));
  // Same command, same bytes.
  const auto out2 = (dir / "zz2.csv").string();
  ASSERT_EQ(RunUsvid("simulate --vessel odin3dof --maneuver zigzag:20/20 --noise 0.01 --seed 4 "
                     "--effect current=0.3 --out " +
                     out2)
                .exit_code,
            0);
  EXPECT_EQ(ReadTextFile(out), ReadTextFile(out2));
}

// --logged: the record carries the wind aboard and the current in body axes, the truth file says
// which and marks the gusts measured; a disturbance the run does not make is exit 2, no file.
TEST_F(SimulateCliTest, LoggedDisturbancesAreChannels) {
  const auto dir = FreshTempDir();
  const auto out = (dir / "lg.csv").string();
  const auto r = RunUsvid(
      "simulate --vessel odin-hs --maneuver random-steps --duration 30 --effect current=0.3 "
      "--gusts 8 --logged wind,current --out " +
      out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Dataset d = ReadDatasetCsv(out);
  for (const char* c : {"wind_speed", "wind_direction", "current_u", "current_v"})
    EXPECT_TRUE(d.Has(c)) << c;
  const nlohmann::json truth = ReadJsonFile((dir / "lg.truth.json").string());
  EXPECT_EQ(truth.at("logged"), nlohmann::json({"wind", "current"}));
  EXPECT_EQ(truth.at("gusts").at("measured"), true);
  const auto bad = (dir / "bad.csv").string();
  const auto refused =
      RunUsvid("simulate --vessel odin-hs --maneuver random-steps --logged current --out " + bad);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_THAT(refused.err, HasSubstr("--logged: 'current' logs the current, and no current"));
  EXPECT_FALSE(fs::exists(bad));
}

// Multi-rate sensors: GPS channels at 5 Hz are empty on the rows between their samples.
TEST_F(SimulateCliTest, MultiRateSensorsLeaveEmptyCells) {
  const auto dir = FreshTempDir();
  const auto out = (dir / "mr.csv").string();
  const auto r = RunUsvid(
      "simulate --vessel eb2dof --maneuver random-steps --duration 60 "
      "--rates imu=50,gps=5 --out " +
      out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Dataset d = ReadDatasetCsv(out);
  EXPECT_NEAR(d.t()(1) - d.t()(0), 0.02, 1e-12);
  EXPECT_EQ(d.Get("north").SampleCount(), 301);
  EXPECT_TRUE(d.Get("r").FullySampled());
  // GPS at 5 Hz in a 50 Hz log fills a tenth of the rows: held sparse, as `usvid info` says.
  EXPECT_TRUE(d.Get("north").Sparse());
  EXPECT_FALSE(d.Get("r").Sparse());
  const auto info = RunUsvid("info --data " + out);
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_THAT(info.out, HasSubstr("; sparse: north, east"));
}

// Bad input: exit 2, one line naming the option, and no output file left behind.
TEST_F(SimulateCliTest, BadInputIsRefusedWithoutOutput) {
  const auto dir = FreshTempDir();
  const auto out = (dir / "x.csv").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--vessel titanic --maneuver zigzag", "unknown vessel"},
      {"--vessel odin3dof --maneuver spiral", "unknown maneuver"},
      {"--vessel odin3dof --maneuver zigzag --effect gust=3", "unknown effect"},
      {"--vessel odin3dof --maneuver zigzag --effect wind=1", "odin3dof has no wind model"},
      {"--vessel odin3dof --maneuver zigzag --wind 3:90", "no wind inputs"},
      {"--vessel odin3dof --maneuver zigzag --effect current=abc", "'abc' is not a number"},
      {"--vessel msd --maneuver zigzag", "no heading"},
      {"--vessel odin3dof --maneuver zigzag --duration -5", "--duration"},
      {"--vessel odin3dof --maneuver zigzag --dt 0", "--dt"},
      {"--vessel odin3dof", "exactly one of --maneuver and --inputs"},
      {"--vessel odin3dof --inputs /nonexistent.csv", "/nonexistent.csv"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = RunUsvid("simulate " + args + " --out " + out);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_THAT(r.err, HasSubstr(message)) << args;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
  const auto missing = RunUsvid("simulate --vessel odin3dof --maneuver zigzag --out " +
                                (dir / "no" / "x.csv").string());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.err, HasSubstr("does not exist"));
  // An inputs file without the vessel's input columns names the missing column.
  testing::WriteText(dir / "in.csv", "t,f\n0,1\n1,2\n");
  const auto cols = RunUsvid("simulate --vessel odin3dof --inputs " + (dir / "in.csv").string() +
                             " --out " + out);
  EXPECT_EQ(cols.exit_code, 2);
  EXPECT_THAT(cols.err, HasSubstr("no input column 'tau_x'"));
}

}  // namespace
}  // namespace usvid
