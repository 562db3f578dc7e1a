// `usvid compare --cv runs` and a suite's "cv": "runs" as a user meets them
// (docs/compare.md#cross-validation-over-runs): on three simulated KVLCC2 records, given as a
// suite on measured data, each run is left out in turn and scored by the fits that left it out;
// summary.md and results.json hold every run's score and the means over the runs; the same
// command resumes from the cells. Too few runs, an unknown --cv and a simulated suite are
// exit 2, one line naming the suite and the problem, nothing written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <tuple>

#include "core/csv_tokenizer.h"
#include "core/json_file.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using ::testing::HasSubstr;
using testing::RunUsvid;
using testing::WriteText;
namespace fs = std::filesystem;

class CrossValidationCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = FreshTempDir();
    for (const auto& [file, maneuver, seconds] :
         {std::tuple{"zz1.csv", "zigzag:20/20", 500}, std::tuple{"zz2.csv", "zigzag:-20/20", 501},
          std::tuple{"tc.csv", "turning:35", 900}})
      ASSERT_EQ(RunUsvid("simulate --vessel kvlcc2 --maneuver " + std::string(maneuver) +
                         " --duration " + std::to_string(seconds) + " --noise 0.005 --seed " +
                         std::to_string(seconds) + " --out " + (dir_ / file).string())
                    .exit_code,
                0);
  }
  // Two training entries and one test entry, each with the maneuver it was run with.
  static nlohmann::json Suite(bool cv) {
    nlohmann::json s = {
        {"name", "tiny"},
        {"vessels", {"kvlcc2"}},
        {"data",
         {{"train",
           {{{"name", "zz 20"}, {"file", "zz1.csv"}, {"maneuver", "zigzag:20/20"}},
            {{"name", "turn 35"}, {"file", "tc.csv"}, {"maneuver", "turning:35"}}}},
          {"test", {{{"name", "zz -20"}, {"file", "zz2.csv"}, {"maneuver", "zigzag:-20/20"}}}}}},
        {"methods", {"lti", "nomoto"}}};
    if (cv) s["cv"] = "runs";
    return s;
  }
  static long Lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }
  fs::path dir_;
};

// Every method is fitted three times, each time on the two runs it does not score: every run is
// scored once per method, under the one training label; summary.md opens the section with the
// means and intervals, and results.json has every run's value. Run again, nothing is refitted.
TEST_F(CrossValidationCliTest, EachRunIsScoredByTheFitsThatLeftItOut) {
  WriteText(dir_ / "suite.json", Suite(true).dump());
  const fs::path out = dir_ / "out";
  const std::string command =
      "compare --suite " + (dir_ / "suite.json").string() + " --out " + out.string();
  const auto r = RunUsvid(command);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("6 fits x the run each leaves out, of 3 runs"));
  EXPECT_THAT(r.err, HasSubstr("kvlcc2/all but zz -20/lti"));

  const nlohmann::json results = ReadJsonFile((out / "results.json").string());
  std::set<std::pair<std::string, std::string>> scored;
  for (const nlohmann::json& row : results.at("rows")) {
    EXPECT_EQ(row.at("train_maneuver"), "leave-one-run-out");
    EXPECT_TRUE(scored
                    .insert({row.at("method").get<std::string>(),
                             row.at("test_maneuver").get<std::string>()})
                    .second)
        << row.dump();
  }
  EXPECT_EQ(scored.size(), 6u);
  const nlohmann::json& cv = results.at("cross_validation");
  EXPECT_EQ(cv.at("runs"), nlohmann::json({"zz 20", "turn 35", "zz -20"}));
  const nlohmann::json& fit = cv.at("criteria").at(0);
  EXPECT_EQ(fit.at("criterion"), "free_run_fit_percent");
  ASSERT_EQ(fit.at("methods").size(), 2u);
  for (const nlohmann::json& m : fit.at("methods")) {
    EXPECT_EQ(m.at("values").size() + m.at("missing").size(), 3u) << m.dump();
    for (const auto& [run, value] : m.at("values").items()) {
      EXPECT_TRUE(value.is_number()) << run;
      // The value is the run's row, the one scored by the fit that left it out.
      for (const nlohmann::json& row : results.at("rows")) {
        if (row.at("method") == m.at("method") && row.at("test_maneuver") == run) {
          EXPECT_DOUBLE_EQ(value.get<double>(), row.at("mean_fit_percent").get<double>());
        }
      }
    }
    if (m.at("values").size() > 1) {  // a mean over one run has no interval
      EXPECT_TRUE(m.at("mean").is_number());
      EXPECT_LE(m.at("interval").at(0).get<double>(), m.at("mean").get<double>());
      EXPECT_GE(m.at("interval").at(1).get<double>(), m.at("mean").get<double>());
    }
  }
  std::set<std::string> criteria;
  for (const nlohmann::json& c : cv.at("criteria")) criteria.insert(c.at("criterion"));
  EXPECT_TRUE(criteria.contains("first_overshoot_error_deg"));
  EXPECT_TRUE(criteria.contains("second_overshoot_error_deg"));
  EXPECT_TRUE(criteria.contains("tactical_diameter_error_percent"));
  const std::string summary = ReadTextFile((out / "summary.md").string());
  EXPECT_THAT(summary, HasSubstr("## Leave-one-run-out cross-validation"));
  EXPECT_THAT(summary, HasSubstr("### free-run fit %, per held-out run"));
  EXPECT_THAT(summary, HasSubstr("| zz -20 |"));
  EXPECT_THAT(summary, HasSubstr("trained on leave-one-run-out"));
  EXPECT_EQ(summary.find("nan"), std::string::npos);

  const auto again = RunUsvid(command);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_THAT(again.err, HasSubstr("resuming: 6 of 6 cells"));
  const nlohmann::json resumed = ReadJsonFile((out / "results.json").string());
  EXPECT_EQ(resumed.at("cross_validation"), cv);
}

// --cv runs on the same suite file, without its "cv" key, gives the same folds; the same suite
// without either scores the two training runs' fit on the test run alone.
TEST_F(CrossValidationCliTest, TheFlagCrossValidatesASuiteFile) {
  WriteText(dir_ / "suite.json", Suite(false).dump());
  const auto r = RunUsvid("compare --suite " + (dir_ / "suite.json").string() +
                          " --cv runs --out " + (dir_ / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json results = ReadJsonFile((dir_ / "out" / "results.json").string());
  EXPECT_EQ(results.at("suite").at("cv"), "runs");
  EXPECT_EQ(results.at("rows").size(), 6u);
  EXPECT_TRUE(results.contains("cross_validation"));
}

TEST_F(CrossValidationCliTest, SuitesWithoutRunsToLeaveOutAreRefused) {
  auto refused = [&](const std::string& args, const std::string& what) {
    const fs::path out = dir_ / "out";
    const auto r = RunUsvid("compare " + args + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_THAT(r.err, HasSubstr(what)) << args;
    EXPECT_EQ(Lines(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  };
  nlohmann::json one = Suite(false);
  one["data"] = {{"train", {{{"name", "only"}, {"file", "zz1.csv"}}}}};
  const std::string one_file = (dir_ / "one.json").string();
  WriteText(one_file, one.dump());
  refused("--suite " + one_file + " --cv runs",
          one_file + ": cv: leaving one run out needs at least two runs; the suite has 1 ('only')");
  const std::string suite = (dir_ / "suite.json").string();
  WriteText(suite, Suite(false).dump());
  refused("--suite " + suite + " --cv folds", "--cv 'folds' is unknown (known: runs");
  refused("--quick --cv runs",
          "--cv runs: suite 'quick' is simulated and has no runs to leave out");
  refused("--suite realistic --cv runs", "suite 'realistic' is simulated");
  const std::string simulated = (dir_ / "simulated.json").string();
  WriteText(simulated, R"({"vessels": ["kvlcc2"], "train_maneuvers": ["zigzag:20/20"],
    "test_maneuvers": ["turning:35"], "methods": ["lti"]})");
  refused("--suite " + simulated + " --cv runs",
          simulated + ": cv: a simulated suite has no runs to leave out");
}

}  // namespace
}  // namespace usvid
