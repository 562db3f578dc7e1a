// `usvid compare` resumes a killed run (issue 12): every finished cell is in OUT/cells, and the
// same command run again computes only the cells that are missing, giving the rows an
// uninterrupted run gives. Cells of another suite are refused, never mixed in.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <regex>
#include <thread>

#include "core/csv_tokenizer.h"
#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using testing::RunUsvid;
namespace fs = std::filesystem;

// 8 cells (2 methods x 4 seeds), each a fraction of a second on one thread.
constexpr int kCells = 8;
const char* const kSuite = R"({"name": "resume", "vessels": ["msd"],
  "train_maneuvers": ["random-steps"], "test_maneuvers": ["multisine", "random-steps"],
  "methods": [{"method": "gp", "population": 300, "generations": 8}, "sindy"],
  "noise": [0.01], "seeds": [1, 2, 3, 4], "train_seconds": 60, "test_seconds": 30})";

int CellFiles(const fs::path& out) {
  int n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(out / "cells", ec)) {
    const std::string name = e.path().filename().string();
    n += name.starts_with("cell-") && name.ends_with(".json");
  }
  return n;
}

// The progress lines of cells this run computed: "[i/n] job".
std::vector<std::string> ComputedCells(const std::string& err) {
  std::vector<std::string> jobs;
  const std::regex line(R"(usvid compare: \[\d+/\d+\] (\S+))");
  for (std::sregex_iterator it(err.begin(), err.end(), line), end; it != end; ++it)
    jobs.push_back((*it)[1]);
  return jobs;
}

nlohmann::json Rows(const fs::path& out, bool keep_time = false) {
  nlohmann::json rows = ReadJsonFile((out / "results.json").string()).at("rows");
  if (!keep_time)
    for (auto& row : rows) row.erase("fit_seconds");
  return rows;
}

class ResumeCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = FreshTempDir();
    suite_ = (dir_ / "suite.json").string();
    testing::WriteText(suite_, kSuite);
  }
  std::string Compare(const fs::path& out) const {
    return "compare --suite " + suite_ + " --threads 1 --out " + out.string();
  }
  fs::path dir_;
  std::string suite_;
};

TEST_F(ResumeCliTest, AKilledRunResumedComputesOnlyTheMissingCells) {
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  const auto uninterrupted = RunUsvid(Compare(whole));
  ASSERT_EQ(uninterrupted.exit_code, 0) << uninterrupted.err;
  EXPECT_EQ(ComputedCells(uninterrupted.err).size(), kCells);

  // Kill the run (SIGKILL: no chance to tidy up) once its first cells are written.
  const int pid = testing::StartUsvid(Compare(killed), dir_ / "killed.err");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (CellFiles(killed) < 2 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(pid, SIGKILL);
  ASSERT_EQ(testing::WaitUsvid(pid), 128 + SIGKILL);
  const int kept = CellFiles(killed);
  ASSERT_GE(kept, 2);
  ASSERT_LT(kept, kCells) << "the run finished before it was killed";
  EXPECT_FALSE(fs::exists(killed / "results.json"));

  const auto resumed = RunUsvid(Compare(killed));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.err, HasSubstr("resuming: " + std::to_string(kept) + " of 8 cells"));
  EXPECT_EQ(ComputedCells(resumed.err).size(), static_cast<size_t>(kCells - kept));
  EXPECT_EQ(Rows(killed), Rows(whole));
}

TEST_F(ResumeCliTest, OnlyTheCellsRemovedAreRunAgain) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(RunUsvid(Compare(out)).exit_code, 0);
  const nlohmann::json before = Rows(out, /*keep_time=*/true);
  fs::remove(out / "cells" / "cell-00001.json");
  fs::remove(out / "cells" / "cell-00006.json");

  const auto again = RunUsvid(Compare(out));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  // Jobs are methods x seeds: job 1 is gp with seed 2, job 6 sindy with seed 3 (in the order of
  // their cost, SlowestFirst: this small gp search may come after sindy).
  EXPECT_THAT(ComputedCells(again.err),
              ::testing::UnorderedElementsAre(::testing::EndsWith("gp/noise=0.01/seed=2"),
                                              ::testing::EndsWith("sindy/noise=0.01/seed=3")));
  // The cells kept are the rows as they were, down to the time their fit took.
  const nlohmann::json after = Rows(out, /*keep_time=*/true);
  ASSERT_EQ(after.size(), before.size());
  for (size_t i = 0; i < after.size(); ++i) {
    if (after[i]["seed"] == 2 && after[i]["method"] != "sindy") continue;
    if (after[i]["seed"] == 3 && after[i]["method"] == "sindy") continue;
    EXPECT_EQ(after[i], before[i]) << i;
  }
}

// A run draws its example figure from the free runs its rows were scored on (ResultRow::free_run);
// a resumed run's rows, read back from the cells, have none, and the report runs each model
// again. Both must draw the same figure, to the byte.
TEST_F(ResumeCliTest, AResumedRunDrawsTheFreeRunsTheScoresWereOn) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(RunUsvid(Compare(out)).exit_code, 0);
  const std::string scored = ReadTextFile((out / "run_msd.svg").string());
  ASSERT_THAT(scored, HasSubstr("gp"));
  fs::remove(out / "run_msd.svg");

  const auto resumed = RunUsvid(Compare(out));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.err, HasSubstr("resuming: 8 of 8 cells"));
  EXPECT_TRUE(ComputedCells(resumed.err).empty());
  EXPECT_EQ(ReadTextFile((out / "run_msd.svg").string()), scored);
}

TEST_F(ResumeCliTest, CellsOfAnotherSuiteAreRefusedUnlessFresh) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(RunUsvid(Compare(out)).exit_code, 0);
  nlohmann::json other = nlohmann::json::parse(kSuite);
  other["seeds"] = {7};
  const std::string other_suite = (dir_ / "other.json").string();
  testing::WriteText(other_suite, other.dump());
  const std::string args = "compare --suite " + other_suite + " --threads 1 --out " + out.string();

  const auto refused = RunUsvid(args);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_THAT(refused.err, HasSubstr("cells of another suite"));
  EXPECT_THAT(refused.err, HasSubstr("--fresh"));

  const auto fresh = RunUsvid(args + " --fresh");
  ASSERT_EQ(fresh.exit_code, 0) << fresh.err;
  EXPECT_EQ(ComputedCells(fresh.err).size(), 2u);  // 2 methods x 1 seed, nothing resumed
  EXPECT_EQ(CellFiles(out), 2);
}

TEST_F(ResumeCliTest, ADamagedCellFileIsNamed) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(RunUsvid(Compare(out)).exit_code, 0);
  testing::WriteText(out / "cells" / "cell-00003.json", R"({"job": "msd/random-steps")");
  const auto r = RunUsvid(Compare(out));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("cell-00003.json"));
}

}  // namespace
}  // namespace usvid
