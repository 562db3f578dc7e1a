// The cells a resumable run keeps (cell_store.h): a row read back is the row written, its model
// and optional scores included; a store refuses another suite's or another build's cells; a
// damaged cell file is an InputError naming it.
#include "harness/cell_store.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

Suite SmallSuite() {
  Suite s;
  s.name = "cells";
  s.vessels = {"msd"};
  s.train_maneuvers = {"random-steps"};
  s.test_maneuvers = {"multisine"};
  s.methods = {{"gp", {{"population", 50}}}, {"sindy", nlohmann::json::object()}};
  s.noise = {0.01};
  s.seeds = {1, 2};
  return s;
}

std::vector<ResultRow> Rows(const FitJob& job) {
  ResultRow ok;
  ok.vessel = job.vessel.Name();
  ok.train_maneuver = job.train_maneuver;
  ok.test_maneuver = "multisine";
  ok.method = job.method.Label();
  ok.noise = job.noise;
  ok.seed = job.seed;
  ok.test_seed = job.seed + 1000;
  ok.fit_percent = {{"v", 97.25}, {"x", 0.1 + 0.2}};  // 0.30000000000000004 must survive
  ok.nrmse = {{"v", 0.0275}};
  ok.channel_fit_percent = {{"v", 97.25}};
  ok.mean_fit_percent = 48.675;
  ok.regime_fit_percent = {{"planing", -12.5}};
  ok.fit_seconds = 1.0 / 3.0;
  ok.terms = 4;
  ok.precision = 0.75;
  ok.recall = 1.0;
  ok.parameter_error = 1e-9;
  ok.model = {{"equations", {{"v", "-0.5*v + u"}}}};
  ResultRow failed = ok;
  failed.status = "failed: free run: the test maneuver lacks input tau_y";
  return {ok, failed};
}

void ExpectSameRows(const std::vector<ResultRow>& a, const std::vector<ResultRow>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].ToCellJson(), b[i].ToCellJson()) << i;
    EXPECT_EQ(a[i].model, b[i].model) << i;  // the report plots it
  }
}

class CellStoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    out_ = fs::temp_directory_path() /
           ("usvid_cells_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(out_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(out_);
  }
  fs::path out_;
  Suite suite_ = SmallSuite();
  std::vector<FitJob> jobs_ = FitJobs(suite_);
};

TEST_F(CellStoreTest, ARowReadBackIsTheRowWritten) {
  const std::vector<ResultRow> rows = Rows(jobs_[1]);
  const std::vector<ResultRow> back = CellRows(CellJson(jobs_[1], rows), jobs_[1].Id(), "test");
  ExpectSameRows(back, rows);
  EXPECT_EQ(back[0].fit_percent.at("x"), 0.1 + 0.2);  // bit for bit
  EXPECT_EQ(back[0].fit_seconds, 1.0 / 3.0);
  EXPECT_FALSE(back[1].precision.has_value());  // a failed row carries no scores
}

TEST_F(CellStoreTest, LoadsTheCellsSavedAndOnlyThose) {
  ASSERT_EQ(jobs_.size(), 4u);
  const CellStore store(out_.string(), suite_, "build-a", false);
  store.Save(2, jobs_[2], Rows(jobs_[2]));
  store.Save(0, jobs_[0], Rows(jobs_[0]));
  const CellStore reopened(out_.string(), suite_, "build-a", false);
  const auto done = reopened.Load(jobs_);
  ASSERT_EQ(done.size(), 2u);
  ExpectSameRows(done.at(0), Rows(jobs_[0]));
  ExpectSameRows(done.at(2), Rows(jobs_[2]));
}

TEST_F(CellStoreTest, FreshForgetsTheCells) {
  CellStore(out_.string(), suite_, "build-a", false).Save(1, jobs_[1], Rows(jobs_[1]));
  EXPECT_TRUE(CellStore(out_.string(), suite_, "build-a", true).Load(jobs_).empty());
}

TEST_F(CellStoreTest, RefusesAnotherSuiteOrBuild) {
  CellStore(out_.string(), suite_, "build-a", false).Save(1, jobs_[1], Rows(jobs_[1]));
  Suite other = suite_;
  other.seeds = {1, 2, 3};
  EXPECT_THROW(
      {
        try {
          CellStore(out_.string(), other, "build-a", false);
        } catch (const InputError& e) {
          EXPECT_THAT(e.what(), HasSubstr("another suite"));
          throw;
        }
      },
      InputError);
  EXPECT_THROW(
      {
        try {
          CellStore(out_.string(), suite_, "build-b", false);
        } catch (const InputError& e) {
          EXPECT_THAT(e.what(), HasSubstr("another usvid build (build-a, this is build-b)"));
          throw;
        }
      },
      InputError);
}

TEST_F(CellStoreTest, ADamagedRecordOfTheSuiteIsNamed) {
  fs::create_directories(out_ / "cells");
  for (const char* text :
       {"[1, 2]", R"({"suite": {}})", R"({"suite": {}, "usvid_build": 7})", R"({"suite": )"}) {
    std::ofstream(out_ / "cells" / "suite.json") << text;
    EXPECT_THROW(
        {
          try {
            CellStore(out_.string(), suite_, "build-a", false);
          } catch (const InputError& e) {
            EXPECT_THAT(e.what(), HasSubstr("cells/suite.json")) << text;
            throw;
          }
        },
        InputError)
        << text;
  }
  // --fresh starts over whatever was there.
  EXPECT_NO_THROW(CellStore(out_.string(), suite_, "build-a", true));
}

TEST_F(CellStoreTest, ACellOfAnotherJobOrDamagedIsNamed) {
  const CellStore store(out_.string(), suite_, "build-a", false);
  store.Save(3, jobs_[1], Rows(jobs_[1]));  // job 1's rows under job 3's name
  EXPECT_THROW(
      {
        try {
          store.Load(jobs_);
        } catch (const InputError& e) {
          EXPECT_THAT(e.what(), HasSubstr("cell-00003.json: holds job"));
          throw;
        }
      },
      InputError);
  std::ofstream(out_ / "cells" / "cell-00003.json") << R"({"job": 3, "rows": []})";
  EXPECT_THROW(store.Load(jobs_), InputError);
}

}  // namespace
}  // namespace usvid
