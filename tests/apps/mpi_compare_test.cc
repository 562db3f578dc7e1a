// `mpirun -n N usvid compare` (issue 12, built with -DUSVID_WITH_MPI=ON): the cells go to
// whichever rank is free, rank 0 writes the outputs, and the rows are those of one process: each
// cell depends on its seed alone. Cells a method cannot fit are rows saying why, on whichever rank
// ran them; a killed MPI run resumes like any other.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>

#include "core/csv_tokenizer.h"
#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

struct MpiResult {
  int exit_code;
  std::string err;
};

// mpirun on loopback, oversubscribed (CI has 2 cores); allowed as root, as CI runs.
MpiResult MpiRun(int ranks, const std::string& args, const fs::path& dir) {
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  ::setenv("OMPI_MCA_btl", "self,vader,tcp", 1);
  ::setenv("OMPI_MCA_btl_tcp_if_include", "lo", 1);
  const fs::path err = dir / ("mpirun_" + std::to_string(ranks) + ".err");
  const std::string cmd = std::string(USVID_MPIEXEC) + " -n " + std::to_string(ranks) +
                          " --oversubscribe " + testing::UsvidBinary() + " " + args + " 2>" +
                          err.string() + " >/dev/null";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status),
          ReadTextFile(err.string())};
}

// The cells each rank computed, from its progress lines "rank R: [k/n] job".
std::map<int, int> CellsPerRank(const std::string& err) {
  std::map<int, int> cells;
  const std::regex line(R"(usvid compare: rank (\d+): \[\d+/\d+\] )");
  for (std::sregex_iterator it(err.begin(), err.end(), line), end; it != end; ++it)
    ++cells[std::stoi((*it)[1])];
  return cells;
}

nlohmann::json Rows(const fs::path& out) {
  nlohmann::json rows = ReadJsonFile((out / "results.json").string()).at("rows");
  for (auto& row : rows) row.erase("fit_seconds");
  return rows;
}

class MpiCompareTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = FreshTempDir();
    suite_ = (dir_ / "suite.json").string();
    // 12 cells; fossen-ceres cannot fit msd (failed rows), odin3dof's cells are heavier.
    testing::WriteText(suite_, R"({"name": "mpi", "vessels": ["msd", "odin3dof"],
      "train_maneuvers": ["random-steps"], "test_maneuvers": ["multisine", "random-steps"],
      "methods": [{"method": "gp", "population": 200, "generations": 5}, "sindy",
                  "fossen-ceres"],
      "noise": [0.01], "seeds": [1, 2], "train_seconds": 60, "test_seconds": 30})");
  }
  std::string Compare(const fs::path& out) const {
    return "compare --suite " + suite_ + " --threads 1 --out " + out.string();
  }
  fs::path dir_;
  std::string suite_;
};

TEST_F(MpiCompareTest, TwoRanksGiveTheRowsOfOne) {
  const MpiResult one = MpiRun(1, Compare(dir_ / "one"), dir_);
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const MpiResult two = MpiRun(2, Compare(dir_ / "two"), dir_);
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_THAT(two.err, HasSubstr("on 2 ranks"));
  // Both ranks computed cells, every cell once: each takes the next cell when it is free.
  const std::map<int, int> cells = CellsPerRank(two.err);
  ASSERT_EQ(cells.size(), 2u) << two.err;
  EXPECT_EQ(cells.at(0) + cells.at(1), 12) << two.err;
  const nlohmann::json rows = Rows(dir_ / "two");
  EXPECT_EQ(rows, Rows(dir_ / "one"));
  ASSERT_EQ(rows.size(), 24u);
  int failed = 0;
  for (const auto& row : rows) failed += row["status"] != "ok";
  EXPECT_EQ(failed, 2 * 2);  // fossen-ceres on msd: 2 seeds x 2 test maneuvers, with the reason
  for (const char* f : {"results.csv", "summary.md", "report.html"})
    EXPECT_TRUE(fs::exists(dir_ / "two" / f)) << f;
}

TEST_F(MpiCompareTest, TwoRanksResumeWhatOneRankLeft) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(MpiRun(1, Compare(out), dir_).exit_code, 0);
  const nlohmann::json whole = Rows(out);
  for (const char* cell : {"cell-00000.json", "cell-00005.json", "cell-00009.json"})
    fs::remove(out / "cells" / cell);
  const MpiResult resumed = MpiRun(2, Compare(out), dir_);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.err, HasSubstr("resuming: 9 of 12 cells"));
  const std::map<int, int> cells = CellsPerRank(resumed.err);
  int computed = 0;
  for (const auto& [rank, n] : cells) computed += n;
  EXPECT_EQ(computed, 3) << resumed.err;
  EXPECT_EQ(Rows(out), whole);
}

TEST_F(MpiCompareTest, BadInputEndsEveryRankWithExitCode2) {
  const MpiResult r = MpiRun(
      2, "compare --suite " + (dir_ / "missing.json").string() + " --out " + (dir_ / "x").string(),
      dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("missing.json"));
}

}  // namespace
}  // namespace usvid
