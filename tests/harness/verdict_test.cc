// The verdict of `usvid compare` (harness/verdict.h): per vessel, training maneuver and metric,
// the methods ranked by Friedman over paired (noise, seed) cells, ties by Holm-adjusted Wilcoxon.
#include "harness/verdict.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>

namespace usvid {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::UnorderedElementsAre;

class VerdictTest : public ::testing::Test {
 protected:
  struct Cell {
    double noise;
    uint64_t seed;
  };

  VerdictTest() { suite_.train_maneuvers = {"random-steps"}; }

  // noise {0.005, 0.02} x seeds 1..5, the first n of them (noise 0.005 first).
  static std::vector<Cell> Cells(size_t n = 10) {
    std::vector<Cell> cells;
    for (double noise : {0.005, 0.02})
      for (uint64_t seed = 1; seed <= 5; ++seed) cells.push_back({noise, seed});
    cells.resize(n);
    return cells;
  }
  // A cell's level, spread over 80..86.3 % in no order, so that cells differ in scale.
  static double Base(size_t i) { return 80.0 + 0.7 * static_cast<double>((i * 7) % 10); }
  // Per-cell noise in [-0.8, 0.8], smaller than a 5-point margin.
  static double Jitter(size_t i) { return 0.4 * static_cast<double>((i * 3) % 5) - 0.8; }
  // +-1 in no order, five of each; the first three -1.
  static double Sign(size_t i) {
    static constexpr double kSigns[] = {-1, -1, -1, 1, 1, -1, 1, 1, -1, 1};
    return kSigns[i];
  }

  static ResultRow Row(const std::string& method, const std::string& test, const Cell& cell,
                       double fit) {
    ResultRow r;
    r.vessel = "odin3dof";
    r.train_maneuver = "random-steps";
    r.test_maneuver = test;
    r.method = method;
    r.noise = cell.noise;
    r.seed = cell.seed;
    r.mean_fit_percent = fit;
    r.horizon_fit_percent = {{"5", fit + 5.0}, {"30", fit + 2.0}, {"all", fit}};
    return r;
  }
  // A method's rows on both test maneuvers of the first n cells, the cell's mean fit score(i)
  // (zig-zag 0.3 above it, random steps 0.3 below).
  void Add(const std::string& method, size_t n, const std::function<double(size_t)>& score) {
    const std::vector<Cell> cells = Cells(n);
    for (size_t i = 0; i < cells.size(); ++i) {
      rows_.push_back(Row(method, "zigzag:20/20", cells[i], score(i) + 0.3));
      rows_.push_back(Row(method, "random-steps", cells[i], score(i) - 0.3));
    }
  }
  // A method's rows of one cell: the zig-zag replay's first overshoot error (null: the replay
  // diverged) and a random-steps row without closed-loop criteria.
  void AddReplay(const std::string& method, const Cell& cell, const nlohmann::json& error) {
    rows_.push_back(Row(method, "zigzag:20/20", cell, 80.0));
    rows_.back().closed_loop = nlohmann::json::object({{"first_overshoot_error_deg", error}});
    rows_.push_back(Row(method, "random-steps", cell, 80.0));
  }
  // A 5 points above B, C within 0.2 of A.
  void AddThreeMethods(size_t n) {
    Add("A", n, [](size_t i) { return Base(i); });
    Add("B", n, [](size_t i) { return Base(i) - 5.0 + Jitter(i); });
    Add("C", n, [](size_t i) { return Base(i) + 0.2 * Sign(i); });
  }

  static const VerdictEntry& Entry(const std::vector<VerdictEntry>& verdict,
                                   const std::string& metric) {
    for (const VerdictEntry& e : verdict)
      if (e.metric == metric) return e;
    ADD_FAILURE() << "no verdict for " << metric;
    return verdict.at(0);
  }
  static const Standing& Of(const VerdictEntry& e, const std::string& method) {
    for (const Standing& s : e.ranking)
      if (s.method == method) return s;
    ADD_FAILURE() << "no standing for " << method;
    return e.ranking.at(0);
  }
  static std::vector<std::string> Order(const VerdictEntry& e) {
    std::vector<std::string> out;
    for (const Standing& s : e.ranking) out.push_back(s.method);
    return out;
  }
  // The Markdown line of the metric labelled `label`.
  static std::string Line(const std::string& md, const std::string& label) {
    std::istringstream in(md);
    for (std::string line; std::getline(in, line);)
      if (line.starts_with("| " + label + " | ")) return line;
    ADD_FAILURE() << "no line for " << label << " in\n" << md;
    return "";
  }

  Suite suite_;
  std::vector<ResultRow> rows_;
};

// A 5 points above B in every one of the 10 cells (per-cell noise < 1 point), C = A +- 0.2 with
// five signs each way. Friedman: B is last in every block and A, C share the rest, so Q = 15 and
// p ~ 5e-4. A vs B and C vs B: 10 positive pairs, exact p = 2 / 2^10, still < 0.05 after Holm,
// so B is neither tied with the best nor with the one above it. A vs C: signs balanced, p ~ 1,
// so C and A are both bold: the data cannot say which of the two is better.
TEST_F(VerdictTest, ConsistentMarginSeparatesAndEqualMethodsTie) {
  AddThreeMethods(10);
  const std::vector<VerdictEntry> verdict = Verdict(suite_, rows_);
  const VerdictEntry& e = Entry(verdict, "free_run_fit_percent");
  EXPECT_EQ(e.vessel, "odin3dof");
  EXPECT_EQ(e.train_maneuver, "random-steps");
  EXPECT_TRUE(e.higher_is_better);
  EXPECT_EQ(e.cells, 10);
  EXPECT_LT(e.friedman_p, kVerdictAlpha);
  ASSERT_EQ(e.ranking.size(), 3u);
  EXPECT_THAT((std::vector<std::string>{e.ranking[0].method, e.ranking[1].method}),
              UnorderedElementsAre("A", "C"));
  EXPECT_EQ(e.ranking[2].method, "B");
  EXPECT_TRUE(Of(e, "A").tied_with_best);
  EXPECT_TRUE(Of(e, "C").tied_with_best);
  EXPECT_TRUE(e.ranking[1].tied_with_previous);
  EXPECT_FALSE(Of(e, "B").tied_with_best);
  EXPECT_FALSE(Of(e, "B").tied_with_previous);
  EXPECT_LT(Of(e, "B").p_vs_best, kVerdictAlpha);
  EXPECT_DOUBLE_EQ(Of(e, "B").mean_rank, 1.0);
  EXPECT_DOUBLE_EQ(Of(e, "A").mean_rank + Of(e, "C").mean_rank, 5.0);
  EXPECT_EQ(Of(e, "A").cells, 10);
  EXPECT_EQ(Of(e, "A").runs, 20);
  EXPECT_EQ(Of(e, "A").failed, 0);
  EXPECT_TRUE(e.failing.empty());
  EXPECT_FALSE(e.ceiling.has_value());
}

// The same margins over 3 cells (noise 0.005, seeds 1..3), C 0.2 below A in all three: Friedman
// now does separate them (ranks 3, 2, 1 in every block: Q = 6, p = e^-3 = 0.0498), but with 3
// pairs the most extreme Wilcoxon outcome (all signs alike) has two-sided p = 2 / 2^3 = 0.25,
// and Holm only raises it. No pairwise test can reach 0.05, so every method is tied with the
// best: three cells cannot tell the methods apart, however large the margin.
TEST_F(VerdictTest, ThreeCellsCannotSeparateMethods) {
  AddThreeMethods(3);
  const std::vector<VerdictEntry> verdict = Verdict(suite_, rows_);
  const VerdictEntry& e = Entry(verdict, "free_run_fit_percent");
  EXPECT_EQ(e.cells, 3);
  EXPECT_NEAR(e.friedman_p, std::exp(-3.0), 1e-9);
  ASSERT_EQ(e.ranking.size(), 3u);
  EXPECT_EQ(Order(e), (std::vector<std::string>{"A", "C", "B"}));
  for (const Standing& s : e.ranking) {
    EXPECT_TRUE(s.tied_with_best) << s.method;
    EXPECT_TRUE(s.tied_with_previous) << s.method;
    EXPECT_GE(s.p_vs_best, 0.25) << s.method;
  }
}

// A 5 points above B everywhere, but in cell 7 A's zig-zag free run diverged with fit -1e5 %
// (cell mean ~ -5e4). A mean over cells would put A last by thousands of points; ranks only
// move A from first to second in that one cell: mean ranks 1.9 and 1.1, A still first, and no
// clamping of the score is needed. The median is untouched and the run is counted as diverged.
TEST_F(VerdictTest, DivergedRunCostsOneRankInOneCell) {
  Add("A", 10, [](size_t i) { return Base(i) + 5.0; });
  Add("B", 10, [](size_t i) { return Base(i); });
  for (ResultRow& r : rows_)
    if (r.method == "A" && r.test_maneuver == "zigzag:20/20" && r.noise == 0.02 && r.seed == 3) {
      r.mean_fit_percent = -1e5;
      r.diverged = true;
    }
  const std::vector<VerdictEntry> verdict = Verdict(suite_, rows_);
  const VerdictEntry& e = Entry(verdict, "free_run_fit_percent");
  EXPECT_EQ(Order(e), (std::vector<std::string>{"A", "B"}));
  EXPECT_DOUBLE_EQ(Of(e, "A").mean_rank, 1.9);
  EXPECT_DOUBLE_EQ(Of(e, "B").mean_rank, 1.1);
  EXPECT_LT(e.friedman_p, kVerdictAlpha);
  EXPECT_GT(Of(e, "A").median, 80.0);
  EXPECT_EQ(Of(e, "A").diverged, 1);
  EXPECT_EQ(Of(e, "A").runs, 20);
  EXPECT_THAT(Line(VerdictMarkdown(verdict), "free-run fit %"), HasSubstr("(1/20 diverged)"));
}

// "nominal" (the true simulator) is the ceiling, not a contender: it is not ranked even though it
// beats everyone, and the ceiling is the median of its cell scores (each the mean over the test
// maneuvers: cells 95..104, median 99.5), written to the JSON as "nominal".
TEST_F(VerdictTest, NominalIsTheCeilingNotRanked) {
  AddThreeMethods(10);
  Add("nominal", 10, [](size_t i) { return 95.0 + static_cast<double>((i * 3) % 10); });
  const std::vector<VerdictEntry> verdict = Verdict(suite_, rows_);
  const VerdictEntry& e = Entry(verdict, "free_run_fit_percent");
  EXPECT_THAT(Order(e), UnorderedElementsAre("A", "B", "C"));
  ASSERT_TRUE(e.ceiling.has_value());
  EXPECT_NEAR(*e.ceiling, 99.5, 1e-9);
  EXPECT_TRUE(e.failing.empty());
  EXPECT_NEAR(VerdictJson(verdict).at(0).at("nominal").get<double>(), 99.5, 1e-9);
}

// F's fit failed in every cell: it has no score to rank, so it is listed in `failing` and not
// ranked. D is 5 points above A but its fit failed in cell 4 (every test row "failed: ..."): the
// cell stays paired and D counts as the worst there (mean ranks 1.9 and 1.1, D still first),
// with failed = 1; a method that fails must not escape by dropping its bad cells.
TEST_F(VerdictTest, FailedFitsAreWorstOrListed) {
  Add("A", 10, [](size_t i) { return Base(i); });
  Add("D", 10, [](size_t i) { return Base(i) + 5.0; });
  Add("F", 10, [](size_t i) { return Base(i) + 10.0; });
  for (ResultRow& r : rows_)
    if (r.method == "F" || (r.method == "D" && r.noise == 0.005 && r.seed == 5))
      r.status = "failed: singular normal equations";
  const std::vector<VerdictEntry> verdict = Verdict(suite_, rows_);
  const VerdictEntry& e = Entry(verdict, "free_run_fit_percent");
  EXPECT_EQ(Order(e), (std::vector<std::string>{"D", "A"}));
  EXPECT_EQ(e.failing, std::vector<std::string>{"F"});
  EXPECT_EQ(e.cells, 10);
  EXPECT_EQ(Of(e, "D").failed, 1);
  EXPECT_EQ(Of(e, "D").cells, 10);
  EXPECT_EQ(Of(e, "D").runs, 18);
  EXPECT_DOUBLE_EQ(Of(e, "D").mean_rank, 1.9);
  EXPECT_EQ(Of(e, "A").failed, 0);
  const std::string line = Line(VerdictMarkdown(verdict), "free-run fit %");
  EXPECT_THAT(line, HasSubstr("(1 of 10 cells failed)"));
  EXPECT_THAT(line, HasSubstr("; F failed in every cell"));
}

// A method that failed in half of its cells or more has an infinite median (failed cells score
// worst): the summary says so in words, not "-inf".
TEST_F(VerdictTest, AMostlyFailedMethodShowsNoMedian) {
  Add("A", 10, [](size_t i) { return Base(i); });
  Add("E", 10, [](size_t i) { return Base(i) - 5.0; });
  for (ResultRow& r : rows_)
    if (r.method == "E" && r.seed % 2 == 1) r.status = "failed: too few steady windows";
  const std::vector<VerdictEntry> verdict = Verdict(suite_, rows_);
  const std::string line = Line(VerdictMarkdown(verdict), "free-run fit %");
  EXPECT_THAT(line, HasSubstr("E no median ("));
  EXPECT_THAT(line, Not(HasSubstr("inf")));
  EXPECT_EQ(Entry(verdict, "free_run_fit_percent").ranking.back().method, "E");
}

// The zig-zag's first overshoot: only the zig-zag rows carry it (the random-steps rows do not
// count), lower |error| is better, so P (errors -0.5.., negative: |error| counts) beats R (~1 deg)
// beats Q (~3 deg). R's replay diverged in cell 3 (null): an infinite error, worse than Q's 3 deg
// there, so R loses one rank in that cell only (mean ranks 3, 1.9, 1.1).
TEST_F(VerdictTest, ClosedLoopErrorRankedLowerAbsoluteBetterNullInfinite) {
  const std::vector<Cell> cells = Cells();
  for (size_t i = 0; i < cells.size(); ++i) {
    const double d = 0.05 * static_cast<double>(i);
    AddReplay("P", cells[i], -0.5 - d);
    AddReplay("Q", cells[i], 3.0 + d);
    AddReplay("R", cells[i], i == 3 ? nlohmann::json() : nlohmann::json(1.0 + d));
  }
  const std::vector<VerdictEntry> verdict = Verdict(suite_, rows_);
  const VerdictEntry& e = Entry(verdict, "first_overshoot_error_deg");
  EXPECT_FALSE(e.higher_is_better);
  EXPECT_EQ(e.cells, 10);
  EXPECT_EQ(Order(e), (std::vector<std::string>{"P", "R", "Q"}));
  EXPECT_DOUBLE_EQ(Of(e, "P").mean_rank, 3.0);
  EXPECT_DOUBLE_EQ(Of(e, "R").mean_rank, 1.9);
  EXPECT_DOUBLE_EQ(Of(e, "Q").mean_rank, 1.1);
  EXPECT_NEAR(Of(e, "P").median, 0.725, 1e-9);
  EXPECT_TRUE(std::isfinite(Of(e, "R").median));
  EXPECT_EQ(Of(e, "R").runs, 10);
  EXPECT_LT(e.friedman_p, kVerdictAlpha);
  EXPECT_FALSE(Of(e, "Q").tied_with_best);
  // The criteria no row carries get no verdict.
  for (const VerdictEntry& other : verdict) {
    EXPECT_NE(other.metric, "second_overshoot_error_deg");
    EXPECT_NE(other.metric, "tactical_diameter_error_m");
  }
}

// A failed row counts as the worst score only for the metrics of its own test maneuver. Here D's
// zig-zag replays are the best in every cell and only its random-steps evaluation failed in
// cell 4: the random-steps rows carry no overshoot, so the first overshoot's verdict must not
// see that failure (run_suite.cc fails a single test row when its evaluation throws).
TEST_F(VerdictTest, FailedRowOfAnotherTestManeuverDoesNotCountForItsMetric) {
  const std::vector<Cell> cells = Cells();
  for (size_t i = 0; i < cells.size(); ++i) {
    AddReplay("D", cells[i], 0.5);
    AddReplay("E", cells[i], 2.0);
    if (i == 4) rows_[rows_.size() - 3].status = "failed: free run threw";  // D's random steps
  }
  const std::vector<VerdictEntry> verdict = Verdict(suite_, rows_);
  const VerdictEntry& e = Entry(verdict, "first_overshoot_error_deg");
  EXPECT_EQ(Order(e), (std::vector<std::string>{"D", "E"}));
  EXPECT_EQ(Of(e, "D").failed, 0);
  EXPECT_DOUBLE_EQ(Of(e, "D").mean_rank, 2.0);
  EXPECT_DOUBLE_EQ(Of(e, "D").median, 0.5);
}

// The Markdown has one table per vessel and training maneuver and one line per metric naming the
// methods best first, tied-with-best in bold (A, C) and the others plain with ">" before them (B);
// the JSON has per entry and per standing the fields of VerdictEntry and Standing (but the label,
// which only the Markdown needs; ceiling as "nominal", only when there is one), so the report and
// results.json say the same.
// On measured data a suite has one seed and no noise levels: one (noise, seed) cell, which no
// test can separate. There each held-out run is a block: A 5 points above B on every one of ten
// runs separates them (exact Wilcoxon p = 2 / 2^10); the same rows in a simulated suite are one
// cell, and tie.
TEST_F(VerdictTest, OnMeasuredDataEachHeldOutRunIsABlock) {
  const Cell one{0.0, 1};
  for (size_t i = 0; i < 10; ++i) {
    const std::string run = "run " + std::to_string(i);
    rows_.push_back(Row("A", run, one, Base(i)));
    rows_.push_back(Row("B", run, one, Base(i) - 5.0 + Jitter(i)));
  }
  const VerdictEntry simulated = Entry(Verdict(suite_, rows_), "free_run_fit_percent");
  EXPECT_EQ(simulated.cells, 1);
  EXPECT_TRUE(Of(simulated, "B").tied_with_best);

  suite_.train_data = {SuiteData{}};  // a suite on measured data
  const VerdictEntry measured = Entry(Verdict(suite_, rows_), "free_run_fit_percent");
  EXPECT_EQ(measured.cells, 10);
  EXPECT_EQ(Order(measured), (std::vector<std::string>{"A", "B"}));
  EXPECT_FALSE(Of(measured, "B").tied_with_best);
  EXPECT_LT(measured.friedman_p, 0.05);
}

TEST_F(VerdictTest, MarkdownAndJsonReportTheRanking) {
  AddThreeMethods(10);
  const std::vector<VerdictEntry> verdict = Verdict(suite_, rows_);
  ASSERT_EQ(verdict.size(), 3u);  // free run, 5 s and 30 s horizons; no closed-loop criteria
  const std::string md = VerdictMarkdown(verdict);
  EXPECT_THAT(md, HasSubstr("### odin3dof, trained on random-steps"));
  for (const char* label : {"free-run fit %", "5 s horizon fit %", "30 s horizon fit %"}) {
    const std::string line = Line(md, label);
    EXPECT_THAT(line, HasSubstr("**A**"));
    EXPECT_THAT(line, HasSubstr("**C**"));
    EXPECT_THAT(line, HasSubstr(" > B "));
    EXPECT_THAT(line, Not(HasSubstr("**B**")));
    EXPECT_THAT(line, HasSubstr(" | 10 | "));
  }

  const nlohmann::json j = VerdictJson(verdict);
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), 3u);
  for (const nlohmann::json& entry : j) {
    for (const char* key : {"vessel", "train_maneuver", "metric", "higher_is_better", "cells",
                            "friedman_p", "ranking", "failing"})
      EXPECT_TRUE(entry.contains(key)) << key;
    EXPECT_FALSE(entry.contains("nominal"));
    ASSERT_EQ(entry.at("ranking").size(), 3u);
    for (const nlohmann::json& s : entry.at("ranking"))
      for (const char* key : {"method", "median", "mean_rank", "cells", "failed_cells", "runs",
                              "diverged_runs", "p_vs_best", "tied_with_best", "tied_with_previous"})
        EXPECT_TRUE(s.contains(key)) << key;
  }
  const nlohmann::json& free_run = j.at(0);
  EXPECT_EQ(free_run.at("metric"), "free_run_fit_percent");
  EXPECT_EQ(free_run.at("vessel"), "odin3dof");
  EXPECT_EQ(free_run.at("cells"), 10);
  EXPECT_EQ(free_run.at("ranking").at(2).at("method"), "B");
  EXPECT_EQ(free_run.at("ranking").at(2).at("tied_with_best"), false);
  EXPECT_EQ(free_run.at("ranking").at(0).at("tied_with_best"), true);
  EXPECT_NEAR(free_run.at("friedman_p").get<double>(), verdict[0].friedman_p, 1e-15);
}

// The suite's "pairs" put two methods head to head (the mission's GP-SR against
// Eriksen-Breivik), whatever the ranking between them says: gp[+,-,*,abs] (the suite's gp, by its
// label) 5 points above eb-lr in 8 cells, so the median paired difference is +5 and
// the exact two-sided Wilcoxon p is 2 / 2^8; SINDy, within 0.2 of GP with balanced signs, cannot
// be told from it (p 1 would be the sign test's; the ranks give more than 0.05).
TEST_F(VerdictTest, PairsAreTestedHeadToHead) {
  suite_.methods = {{"gp", {{"operators", "+,-,*,abs"}}}, {"eb-lr", {}}, {"sindy", {}}};
  suite_.pairs = {{"gp", "eb-lr"}, {"gp", "sindy"}};
  Add("gp[+,-,*,abs]", 8, [](size_t i) { return Base(i); });
  Add("eb-lr", 8, [](size_t i) { return Base(i) - 5.0; });
  Add("sindy", 8, [](size_t i) { return Base(i) + 0.2 * Sign(i); });
  const std::vector<VerdictEntry> verdict = Verdict(suite_, rows_);
  const VerdictEntry& fit = Entry(verdict, "free_run_fit_percent");
  ASSERT_EQ(fit.pairs.size(), 2u);
  EXPECT_EQ(fit.pairs[0].a, "gp[+,-,*,abs]");
  EXPECT_EQ(fit.pairs[0].b, "eb-lr");
  EXPECT_EQ(fit.pairs[0].cells, 8);
  EXPECT_NEAR(fit.pairs[0].median_difference, 5.0, 1e-9);
  EXPECT_NEAR(fit.pairs[0].p, 2.0 / 256.0, 1e-12);
  EXPECT_EQ(fit.pairs[1].b, "sindy");
  EXPECT_GT(fit.pairs[1].p, 0.05);
  const std::string md = VerdictMarkdown(verdict);
  EXPECT_THAT(md, HasSubstr("- **gp[+,-,*,abs] against eb-lr** (median of the paired "
                            "differences over the cells both have; two-sided Wilcoxon p, not "
                            "adjusted): free-run fit % +5.00 (p 0.008, 8 cells)"));
  EXPECT_EQ(VerdictJson(verdict)[0]["pairs"][0]["p"].get<double>(), fit.pairs[0].p);
  // Without pairs, no such line.
  suite_.pairs.clear();
  EXPECT_THAT(VerdictMarkdown(Verdict(suite_, rows_)), Not(HasSubstr("against")));
}

}  // namespace
}  // namespace usvid
