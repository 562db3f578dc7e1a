// Determinism (issue 11): the same data and seed give byte-identical model.json at 1 and at 2
// threads for every method, and `compare` gives identical results rows; only the recorded wall
// times may differ.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

namespace fs = std::filesystem;
using testing::FreshTempDir;
using testing::RunUsvid;

// model.json without what measures time.
nlohmann::json Timeless(nlohmann::json j) {
  if (j.contains("train")) j["train"].erase("seconds");
  return j;
}

TEST(DeterminismTest, EveryMethodGivesTheSameModelAtOneAndTwoThreads) {
  const fs::path dir = FreshTempDir();
  const std::string odin = (dir / "odin.csv").string(), grid = (dir / "grid.csv").string(),
                    ship = (dir / "ship.csv").string();
  ASSERT_EQ(RunUsvid("simulate --vessel odin3dof --maneuver random-steps --duration 120 --noise "
                     "0.01 --seed 3 --out " +
                     odin)
                .exit_code,
            0);
  ASSERT_EQ(RunUsvid("simulate --vessel eb2dof --maneuver stepgrid:4/3 --noise 0.005 --seed 3 "
                     "--out " +
                     grid)
                .exit_code,
            0);
  ASSERT_EQ(RunUsvid("simulate --vessel kvlcc2 --maneuver zigzag:20/20 --duration 400 --noise "
                     "0.005 --seed 3 --out " +
                     ship)
                .exit_code,
            0);
  const std::pair<std::string, std::string> runs[] = {
      {"gp", "--vessel odin3dof --population 200 --generations 5 --data " + odin},
      {"sindy", "--vessel odin3dof --data " + odin},
      {"fossen-ceres", "--vessel odin3dof --data " + odin},
      {"eb-lr", "--vessel eb2dof --data " + grid},
      {"refit", "--vessel kvlcc2 --data " + ship},
      {"nominal", "--vessel kvlcc2 --data " + ship},
      {"nomoto", "--vessel kvlcc2 --data " + ship},
  };
  for (const auto& [method, args] : runs) {
    nlohmann::json models[2];
    for (int threads : {1, 2}) {
      const std::string out = (dir / (method + "_" + std::to_string(threads) + ".json")).string();
      const auto r = RunUsvid("identify --method " + method + " " + args + " --seed 7 --threads " +
                              std::to_string(threads) + " --out " + out);
      ASSERT_EQ(r.exit_code, 0) << method << ": " << r.err;
      models[threads - 1] = Timeless(ReadJsonFile(out));
    }
    EXPECT_EQ(models[0], models[1]) << method;
  }
}

TEST(DeterminismTest, CompareGivesTheSameRowsAtOneAndTwoThreads) {
  const fs::path dir = FreshTempDir();
  testing::WriteText(dir / "suite.json", R"({"vessels": ["odin3dof", "msd"],
    "train_maneuvers": ["random-steps"], "test_maneuvers": ["multisine", "random-steps"],
    "methods": [{"method": "gp", "population": 100, "generations": 3}, "sindy", "fossen-ceres"],
    "noise": [0.01], "seeds": [1, 2], "train_seconds": 60, "test_seconds": 30})");
  nlohmann::json results[2];
  for (int threads : {1, 2}) {
    const std::string out = (dir / std::to_string(threads)).string();
    const auto r = RunUsvid("compare --suite " + (dir / "suite.json").string() + " --threads " +
                            std::to_string(threads) + " --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    results[threads - 1] = ReadJsonFile(out + "/results.json").at("rows");
    for (auto& row : results[threads - 1]) row.erase("fit_seconds");
  }
  EXPECT_EQ(results[0], results[1]);
}

}  // namespace
}  // namespace usvid
