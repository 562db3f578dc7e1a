// Leave-one-run-out cross-validation (harness/cross_validation.h, cross_validation_table.h): a
// suite's data entries become its runs, each fold leaves exactly one out and is scored on it
// alone, the verdict ranks over every run, and the table counts what is missing instead of
// averaging it in.
#include "harness/cross_validation.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/error.h"
#include "harness/cross_validation_table.h"
#include "harness/verdict.h"

namespace usvid {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;

class CrossValidationTest : public ::testing::Test {
 protected:
  // Three training files (two of them one entry, joined) and a zig-zag test: four runs. The
  // files need not exist: the suite is only parsed.
  static nlohmann::json Measured() {
    return {{"name", "cv"},
            {"vessels", {"kvlcc2"}},
            {"cv", "runs"},
            {"data",
             {{"train",
               {{{"name", "pair"}, {"file", {"a.dat", "b.dat"}}, {"format", "marin-dat"}},
                {{"name", "turn"}, {"file", "c.csv"}, {"to_s", 300}}}},
              {"test", {{{"name", "zz"}, {"file", "d.csv"}, {"maneuver", "zigzag:20/20"}}}}}},
            {"methods", {"lti", "nomoto"}}};
  }
  static void ExpectRefused(const nlohmann::json& suite, const std::string& what) {
    try {
      ParseSuite(suite, "s.json");
      FAIL() << what;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr("s.json: "));
      EXPECT_THAT(e.what(), HasSubstr(what));
      EXPECT_THAT(std::string(e.what()), Not(HasSubstr("\n")));
    }
  }
};

// Every file of a training entry is a run (named after the entry and the file, read as the
// entry says), and every test entry; each fold is named after the run it leaves out.
TEST_F(CrossValidationTest, EveryEntryAndEveryFileOfATrainingEntryIsARun) {
  const Suite s = ParseSuite(Measured(), "dir/s.json");
  EXPECT_TRUE(s.cv.On());
  EXPECT_THAT(s.test_maneuvers, ElementsAre("pair: a", "pair: b", "turn", "zz"));
  EXPECT_THAT(s.train_maneuvers,
              ElementsAre("all but pair: a", "all but pair: b", "all but turn", "all but zz"));
  ASSERT_EQ(s.test_data.size(), 4u);
  EXPECT_EQ(s.test_data[0].files, std::vector<std::string>{"dir/a.dat"});
  EXPECT_EQ(s.test_data[1].files, std::vector<std::string>{"dir/b.dat"});
  EXPECT_EQ(s.test_data[1].format, "marin-dat");
  EXPECT_EQ(s.test_data[2].to_s, 300);
  EXPECT_EQ(s.test_data[3].maneuver, "zigzag:20/20");
  EXPECT_EQ(s.cv.given_train.size(), 2u);
  EXPECT_EQ(s.cv.given_test.size(), 1u);
  EXPECT_TRUE(s.Measured());
}

// Each fit trains on every run but one and is scored on that one alone: no cell trains on a run
// it tests on, every run is held out exactly once, and the jobs stay apart in the cell store.
TEST_F(CrossValidationTest, EachFoldLeavesOutOneRunAndIsScoredOnItAlone) {
  const Suite s = ParseSuite(Measured(), "s.json");
  std::multiset<std::string> held_out;
  for (const std::string& fold : s.train_maneuvers) {
    const std::vector<std::string> tests = ScoredTests(s, fold);
    const std::vector<std::string> trained = FoldTrainingRuns(s, fold);
    ASSERT_EQ(tests.size(), 1u);
    EXPECT_EQ(fold, FoldName(tests[0]));
    EXPECT_EQ(trained.size(), 3u);
    EXPECT_EQ(std::ranges::count(trained, tests[0]), 0) << fold;
    held_out.insert(tests[0]);
    EXPECT_EQ(TrainingLabel(s, fold), kLeaveOneRunOut);
  }
  EXPECT_EQ(held_out, std::multiset<std::string>(s.test_maneuvers.begin(), s.test_maneuvers.end()));
  const std::vector<FitJob> jobs = FitJobs(s);
  ASSERT_EQ(jobs.size(), 8u);  // four folds x two methods
  std::set<std::string> ids;
  for (const FitJob& j : jobs) ids.insert(j.Id());
  EXPECT_EQ(ids.size(), jobs.size());
  EXPECT_THAT(TrainingLabels(s), ElementsAre(kLeaveOneRunOut));
  // A suite that is not cross-validated scores every fit on every test, under its own name.
  nlohmann::json plain = Measured();
  plain.erase("cv");
  const Suite p = ParseSuite(plain, "s.json");
  EXPECT_THAT(p.train_maneuvers, ElementsAre("pair", "turn"));
  EXPECT_THAT(ScoredTests(p, "pair"), ElementsAre("zz"));
  EXPECT_EQ(TrainingLabel(p, "pair"), "pair");
}

// The suite echoes as it was given, with its "cv" (what results.json and the cell store keep),
// and that echo expands to the same folds; "test" may be left out of a cross-validated suite.
TEST_F(CrossValidationTest, EchoesAsGivenAndParsesBackToTheSameFolds) {
  const Suite s = ParseSuite(Measured(), "s.json");
  const nlohmann::json echo = SuiteToJson(s);
  EXPECT_EQ(echo.at("cv"), "runs");
  EXPECT_EQ(echo.at("data").at("train").size(), 2u);
  EXPECT_EQ(echo.at("data").at("test").size(), 1u);
  const Suite again = ParseSuite(echo, "s.json");
  EXPECT_EQ(again.train_maneuvers, s.train_maneuvers);
  EXPECT_EQ(again.test_maneuvers, s.test_maneuvers);
  EXPECT_EQ(SuiteToJson(again), echo);

  nlohmann::json no_test = Measured();
  no_test["data"].erase("test");
  const Suite t = ParseSuite(no_test, "s.json");
  EXPECT_THAT(t.test_maneuvers, ElementsAre("pair: a", "pair: b", "turn"));
  EXPECT_FALSE(SuiteToJson(t).at("data").contains("test"));
}

// Fewer than two runs, an unknown kind, a simulated suite, two runs of one name and one file's
// same rows listed twice are refused, one line naming the suite.
TEST_F(CrossValidationTest, SuitesItCannotCrossValidateAreRefused) {
  nlohmann::json one = Measured();
  one["data"] = {{"train", {{{"name", "only"}, {"file", "a.csv"}}}}};
  ExpectRefused(one, "cv: leaving one run out needs at least two runs; the suite has 1 ('only')");
  nlohmann::json kind = Measured();
  kind["cv"] = "folds";
  ExpectRefused(kind, "cv: 'folds' is unknown (known: runs");
  nlohmann::json simulated = {{"vessels", {"kvlcc2"}},
                              {"train_maneuvers", {"zigzag:20/20"}},
                              {"test_maneuvers", {"turning:35"}},
                              {"methods", {"lti"}},
                              {"cv", "runs"}};
  ExpectRefused(simulated, "a simulated suite has no runs to leave out");
  nlohmann::json name = Measured();
  name["data"]["test"][0]["name"] = "turn";
  ExpectRefused(name, "two runs are named 'turn'");
  nlohmann::json twice = Measured();
  twice["data"]["test"][0]["file"] = "c.csv";
  twice["data"]["test"][0]["to_s"] = 300;
  ExpectRefused(twice, "'turn' and 'zz' are the same rows of");
  // The same file's other rows are another run: a held-back part of one log.
  twice["data"]["test"][0]["from_s"] = 300;
  twice["data"]["test"][0].erase("to_s");
  EXPECT_NO_THROW(ParseSuite(twice, "s.json"));
}

// Rows of a cross-validated run, built by hand: A and B on four runs, a zig-zag and a turning
// circle among them.
class CrossValidationTableTest : public CrossValidationTest {
 protected:
  CrossValidationTableTest() { suite_ = ParseSuite(Measured(), "s.json"); }
  ResultRow& Add(const std::string& method, const std::string& run, double fit) {
    ResultRow r;
    r.vessel = "kvlcc2";
    r.train_maneuver = kLeaveOneRunOut;
    r.test_maneuver = run;
    r.method = method;
    r.mean_fit_percent = fit;
    r.horizon_fit_percent = {{"5", fit}, {"30", fit}};
    r.closed_loop = {{"status", "not replayable: no maneuver"}};
    rows_.push_back(r);
    return rows_.back();
  }
  static void ZigZag(ResultRow& r, double first, nlohmann::json second) {
    r.closed_loop = {{"status", "ok"},
                     {"measured", {{"first_overshoot_deg", 10.0}, {"second_overshoot_deg", 20.0}}},
                     {"first_overshoot_error_deg", first},
                     {"second_overshoot_error_deg", second}};
  }
  static void Turn(ResultRow& r, double diameter_error_m) {
    r.closed_loop = {{"status", "ok"},
                     {"measured", {{"tactical_diameter_m", 200.0}, {"advance_m", nullptr}}},
                     {"tactical_diameter_error_m", diameter_error_m},
                     {"advance_error_m", nullptr}};
  }
  Suite suite_;
  std::vector<ResultRow> rows_;
};

// Each run's value, the mean over the runs and its interval; a failed fit, a diverged free run
// and a replay without a value are missing and counted; closed-loop errors are absolute, the
// tactical diameter's in % of the measured; a criterion no record gives (advance) is no column.
TEST_F(CrossValidationTableTest, CountsMissingRunsAndNeverAveragesThemIn) {
  Add("A", "pair: a", 60.0);
  Add("A", "pair: b", 70.0);
  Turn(Add("A", "turn", 50.0), -20.0);
  ZigZag(Add("A", "zz", 80.0), -1.5, 2.0);
  Add("B", "pair: a", 40.0).status = "failed: singular";
  Add("B", "pair: b", -1e5).diverged = true;
  Turn(Add("B", "turn", 30.0), 10.0);
  ZigZag(Add("B", "zz", 20.0), 0.5, nullptr);
  rows_.back().closed_loop["status"] = "diverged at 80.0 s (r)";

  const std::vector<CrossValidatedCriterion> table = CrossValidationTable(suite_, rows_);
  std::vector<std::string> keys;
  for (const auto& c : table) keys.push_back(c.key);
  EXPECT_THAT(keys, ElementsAre("free_run_fit_percent", "first_overshoot_error_deg",
                                "second_overshoot_error_deg", "tactical_diameter_error_percent"));
  const CrossValidatedCriterion& fit = table[0];
  EXPECT_THAT(fit.runs, ElementsAre("pair: a", "pair: b", "turn", "zz"));
  const CrossValidatedMethod& a = fit.methods[0];
  const CrossValidatedMethod& b = fit.methods[1];
  EXPECT_EQ(a.method, "A");
  EXPECT_DOUBLE_EQ(a.mean.mean, 65.0);
  EXPECT_LE(a.mean.low, 65.0);
  EXPECT_GE(a.mean.high, 65.0);
  EXPECT_TRUE(a.missing.empty());
  EXPECT_EQ(b.missing.at("pair: a"), "failed");
  EXPECT_EQ(b.missing.at("pair: b"), "diverged");
  EXPECT_DOUBLE_EQ(b.mean.mean, 25.0);
  EXPECT_EQ(b.mean.n, 2);
  EXPECT_THAT(table[1].runs, ElementsAre("zz"));
  EXPECT_DOUBLE_EQ(table[1].methods[0].values.at("zz"), 1.5);
  EXPECT_EQ(table[2].methods[1].missing.at("zz"), "replay diverged");
  EXPECT_THAT(table[3].runs, ElementsAre("turn"));
  EXPECT_DOUBLE_EQ(table[3].methods[0].values.at("turn"), 10.0);  // 20 m of 200 m
  EXPECT_DOUBLE_EQ(table[3].methods[1].values.at("turn"), 5.0);

  const std::string md = CrossValidationMarkdown(suite_, rows_);
  EXPECT_THAT(md, HasSubstr("## Leave-one-run-out cross-validation"));
  EXPECT_THAT(md, HasSubstr("| A | 65.0 ["));
  EXPECT_THAT(md, HasSubstr("(2 missing)"));
  EXPECT_THAT(md, HasSubstr("| pair: a | 60.0 | failed |"));
  EXPECT_THAT(md, HasSubstr("| missing runs | 0 of 4 | 2 of 4 |"));
  EXPECT_THAT(md, Not(HasSubstr("nan")));
  EXPECT_THAT(md, Not(HasSubstr("inf")));

  const nlohmann::json j = CrossValidationJson(suite_, rows_);
  EXPECT_EQ(j.at("runs").size(), 4u);
  EXPECT_EQ(j.at("bootstrap").at("resamples"), kBootstrapResamples);
  const nlohmann::json& jb = j.at("criteria").at(0).at("methods").at(1);
  EXPECT_EQ(jb.at("method"), "B");
  EXPECT_EQ(jb.at("missing_runs"), 2);
  EXPECT_EQ(jb.at("values").size(), 2u);
  EXPECT_DOUBLE_EQ(jb.at("mean").get<double>(), 25.0);
  EXPECT_EQ(jb.at("interval").size(), 2u);
  EXPECT_EQ(j.dump().find("null"), std::string::npos);
}

// The rows share one training label, so the verdict ranks the methods over all the held-out
// runs as its blocks: A 5 points above B on each of eight runs separates them.
TEST_F(CrossValidationTableTest, TheVerdictRanksOverEveryHeldOutRun) {
  nlohmann::json eight = Measured();
  eight["data"]["test"] = nlohmann::json::array();
  for (int k = 0; k < 8; ++k)
    eight["data"]["test"].push_back(
        {{"name", "run " + std::to_string(k)}, {"file", std::to_string(k) + ".csv"}});
  suite_ = ParseSuite(eight, "s.json");
  ASSERT_EQ(suite_.test_maneuvers.size(), 11u);
  for (size_t k = 0; k < suite_.test_maneuvers.size(); ++k) {
    const double level = 50.0 + 3.0 * static_cast<double>((k * 7) % 11);
    Add("A", suite_.test_maneuvers[k], level);
    Add("B", suite_.test_maneuvers[k], level - 5.0);
  }
  const std::vector<VerdictEntry> verdict = Verdict(suite_, rows_);
  ASSERT_FALSE(verdict.empty());
  for (const VerdictEntry& e : verdict) EXPECT_EQ(e.train_maneuver, kLeaveOneRunOut);
  const VerdictEntry& fit = verdict.front();
  EXPECT_EQ(fit.metric, "free_run_fit_percent");
  EXPECT_EQ(fit.cells, 11);
  EXPECT_EQ(fit.ranking.at(0).method, "A");
  EXPECT_FALSE(fit.ranking.at(1).tied_with_best);
}

}  // namespace
}  // namespace usvid
