// Regression tracking against a baseline (harness/regression.h): cells paired by their full key,
// a Wilcoxon signed-rank test per (vessel, method), Holm over the groups, newly failing cells.
#include "harness/regression.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>

#include "core/error.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;

class RegressionTest : public ::testing::Test {
 protected:
  // 3 training x 3 test maneuvers x 2 seeds = 18 cells of one vessel and method, the baseline's
  // fit spread over 60..94 %, every fit taking 2 s.
  static std::vector<ResultRow> Cells(const std::string& method) {
    std::vector<ResultRow> rows;
    for (const char* train : {"random-steps", "zigzag", "turning-circle"})
      for (const char* test : {"multisine", "random-steps", "zigzag"})
        for (uint64_t seed : {1, 2}) {
          ResultRow r;
          r.vessel = "odin3dof";
          r.method = method;
          r.train_maneuver = train;
          r.test_maneuver = test;
          r.noise = 0.01;
          r.seed = seed;
          r.mean_fit_percent = 60.0 + 2.0 * static_cast<double>(rows.size());
          r.fit_seconds = 2.0;
          rows.push_back(r);
        }
    return rows;
  }
  // `rows` with `change` applied to the i-th of them.
  static std::vector<ResultRow> Changed(std::vector<ResultRow> rows,
                                        const std::function<void(size_t, ResultRow&)>& change) {
    for (size_t i = 0; i < rows.size(); ++i) change(i, rows[i]);
    return rows;
  }
  static nlohmann::json ResultsJson(const std::vector<ResultRow>& rows) {
    nlohmann::json j = {{"rows", nlohmann::json::array()}};
    for (const ResultRow& r : rows) j["rows"].push_back(r.ToJson());
    return j;
  }
  static const nlohmann::json& Group(const RegressionReport& report, const std::string& method) {
    for (const auto& g : report.groups)
      if (g.at("method") == method) return g;
    ADD_FAILURE() << "no group " << method;
    return report.groups.at(0);
  }
  const std::string file_ = "prev/results.json";
};

// A uniform 3-point drop in all 18 paired cells is "worse fit": every signed rank is negative, so
// p = 2 / 2^18, and Holm over the three groups (one unchanged, one 3 points better) keeps it far
// below 0.05. The better group is "better fit", not worse, and the Markdown lists worse first.
TEST_F(RegressionTest, UniformDropIsWorseFit) {
  std::vector<ResultRow> before = Cells("a"), now = Changed(Cells("a"), [](size_t, ResultRow&r) {
                                                r.mean_fit_percent -= 3.0;
                                              });
  for (const ResultRow& r : Cells("b")) {
    before.push_back(r);
    now.push_back(r);
  }
  for (const ResultRow& r : Cells("c")) {
    before.push_back(r);
    now.push_back(r);
    now.back().mean_fit_percent += 3.0;
  }
  const RegressionReport report = CompareWithBaseline(now, ResultsJson(before), file_);
  ASSERT_EQ(report.groups.size(), 3u);
  const nlohmann::json& a = Group(report, "a");
  EXPECT_EQ(a.at("verdict"), "worse fit") << a.dump();
  EXPECT_EQ(a.at("pairs"), 18);
  EXPECT_NEAR(a.at("median_difference").get<double>(), -3.0, 1e-9);
  EXPECT_NEAR(a.at("baseline_median_fit_percent").get<double>(), 77.0, 1e-9);
  EXPECT_NEAR(a.at("median_fit_percent").get<double>(), 74.0, 1e-9);
  EXPECT_LT(a.at("p_value").get<double>(), 0.05);
  EXPECT_LT(a.at("p_adjusted").get<double>(), 0.05);
  EXPECT_GT(a.at("p_adjusted").get<double>(), a.at("p_value").get<double>());
  EXPECT_EQ(Group(report, "b").at("verdict"), "same");
  EXPECT_EQ(Group(report, "c").at("verdict"), "better fit");
  EXPECT_EQ(report.worse, 1);
  const std::string md = report.Markdown();
  EXPECT_THAT(md, HasSubstr("| odin3dof | a | 18 | 74.0 | 77.0 | -3.00 |"));
  EXPECT_LT(md.find("worse fit"), md.find("better fit"));
  EXPECT_EQ(md.find("| b |"), std::string::npos);  // "same" is not listed
  EXPECT_THAT(md, HasSubstr("Wilcoxon signed-rank"));
  EXPECT_THAT(md, HasSubstr("Holm"));
}

// Noise of up to +-2 points with no shift (differences symmetric about zero) is "same": the
// signed ranks balance, p = 1, and the median difference is 0.
TEST_F(RegressionTest, NoiseWithoutShiftIsSame) {
  const auto now = Changed(Cells("a"), [](size_t i, ResultRow& r) {
    const double magnitude = 0.5 + 1.5 * static_cast<double>(i / 2) / 8.0;  // 0.5 .. 2
    r.mean_fit_percent += i % 2 == 0 ? magnitude : -magnitude;
  });
  const RegressionReport report = CompareWithBaseline(now, ResultsJson(Cells("a")), file_);
  const nlohmann::json& a = Group(report, "a");
  EXPECT_EQ(a.at("verdict"), "same") << a.dump();
  EXPECT_EQ(a.at("nonzero_pairs"), 18);
  EXPECT_GT(a.at("p_value").get<double>(), 0.5);
  EXPECT_NEAR(a.at("median_difference").get<double>(), 0.0, 1e-9);
  EXPECT_EQ(report.worse, 0);
  EXPECT_THAT(report.Markdown(), HasSubstr("Every group is the same"));
}

// A 3-point drop in only 4 of the 18 cells is "too few pairs to test", not "same" and not
// "worse": the signed-rank test drops the 14 unchanged pairs, and with 4 nonzero pairs the
// smallest two-sided p is 2 / 2^4 = 0.125, so the test cannot tell; the group is listed with its
// medians (median difference 0) for a reader to judge, and is not counted as worse.
TEST_F(RegressionTest, DropInFourCellsIsTooFewPairsToTest) {
  const auto now = Changed(Cells("a"), [](size_t i, ResultRow& r) {
    if (i < 4) r.mean_fit_percent -= 3.0;
  });
  const RegressionReport report = CompareWithBaseline(now, ResultsJson(Cells("a")), file_);
  const nlohmann::json& a = Group(report, "a");
  EXPECT_EQ(a.at("verdict"), "too few pairs to test") << a.dump();
  EXPECT_EQ(a.at("pairs"), 18);
  EXPECT_EQ(a.at("nonzero_pairs"), 4);
  EXPECT_NEAR(a.at("median_difference").get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(a.at("p_value").get<double>(), 0.125, 1e-12);
  EXPECT_EQ(report.worse, 0);
  EXPECT_THAT(report.Markdown(), HasSubstr("too few pairs to test"));
}

// A cell that fitted in the baseline and fails now makes its group "worse fit" although every
// other pair is unchanged, and the Markdown names the cell and why it failed.
TEST_F(RegressionTest, NewlyFailingCellIsWorse) {
  const auto now = Changed(Cells("a"), [](size_t i, ResultRow& r) {
    if (i == 5) r.status = "failed: solver diverged";
  });
  const RegressionReport report = CompareWithBaseline(now, ResultsJson(Cells("a")), file_);
  const nlohmann::json& a = Group(report, "a");
  EXPECT_EQ(a.at("verdict"), "worse fit") << a.dump();
  EXPECT_EQ(a.at("newly_failing"), 1);
  EXPECT_EQ(a.at("pairs"), 17);
  EXPECT_EQ(a.at("newly_failing_cells").at(0).at("seed"), 2);
  EXPECT_EQ(report.worse, 1);
  const std::string md = report.Markdown();
  EXPECT_THAT(md, HasSubstr("worse fit (newly failing: 1 cell)"));
  EXPECT_THAT(md, HasSubstr("random-steps -> zigzag, noise 0.01, seed 2: failed: solver diverged"));
}

// Fit times that doubled in all 6 fits (one pair per fit, shared by its 3 test maneuvers) are
// "slower", counted as worse: p = 2 / 2^6 < 0.05 and the median grew by more than 50 %.
TEST_F(RegressionTest, DoubledFitTimeIsSlower) {
  const auto now = Changed(Cells("a"), [](size_t, ResultRow& r) { r.fit_seconds = 4.0; });
  const RegressionReport report = CompareWithBaseline(now, ResultsJson(Cells("a")), file_);
  const nlohmann::json& a = Group(report, "a");
  EXPECT_EQ(a.at("verdict"), "slower") << a.dump();
  EXPECT_EQ(a.at("fit_seconds").at("pairs"), 6);
  EXPECT_EQ(report.worse, 1);
}

// A baseline row without a field the comparison needs, or with the wrong type, or no "rows" at
// all, is refused with an InputError naming the file, the row and the field.
TEST_F(RegressionTest, BaselineRowMissingFieldThrowsNamingFile) {
  const auto message = [&](const nlohmann::json& baseline) {
    try {
      CompareWithBaseline(Cells("a"), baseline, file_);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no InputError");
  };
  nlohmann::json missing = ResultsJson(Cells("a"));
  missing["rows"][3].erase("mean_fit_percent");
  EXPECT_THAT(message(missing),
              HasSubstr("prev/results.json: rows[3]: no field \"mean_fit_percent\""));
  nlohmann::json wrong = ResultsJson(Cells("a"));
  wrong["rows"][0]["seed"] = "one";
  EXPECT_THAT(message(wrong), HasSubstr("prev/results.json: rows[0]: field \"seed\""));
  EXPECT_THAT(message({{"name", "a suite"}}), HasSubstr("prev/results.json: not a results.json"));
}

}  // namespace
}  // namespace usvid
