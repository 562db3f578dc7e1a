// The verdict of a comparison: per vessel, training maneuver and metric, the methods ranked,
// with ties marked where the data cannot tell two apart.
//
// Cells: a method's score in one (noise level, seed) cell is the mean of its scores over the
// test maneuvers (which share the fitted model, so they are not independent). On measured data
// a cell is one held-out run: the runs are separate records of the vessel, a suite on logs has
// no noise levels and usually one seed, and the question is which model predicts a new run
// better, so the runs are the blocks; a cross-validated suite's rows share one training label
// (harness/cross_validation.h), so its blocks are all its runs, each scored by the fits that
// left it out. The methods' cells are paired (same training data), so the
// test is rank-based and paired: Friedman over the cells (metrics/rank_tests.h), the methods
// ordered by mean rank, and each compared with the best and with the one ranked above it by a
// Wilcoxon signed-rank test, Holm-adjusted over those comparisons. Demsar (2006, JMLR 7) recommends
// the Wilcoxon and Friedman tests for comparing methods over paired cases; Benavoli et al. (2016,
// JMLR 17) the pairwise Wilcoxon tests with Holm's correction as the post-hoc test, rather than
// tests on mean ranks. Two methods are tied when the Friedman test or the adjusted pairwise test
// does not reach kVerdictAlpha. Ranks need no clamping: a diverged run's fit of -1e5 % is simply
// the worst in its cell. A fit that failed counts as the worst score in its cell (a failed cell:
// the fit's, or on measured data the run's); a method that
// failed in every cell is not ranked but listed. The nominal model (the true simulator) is the
// ceiling, not a contender.
//
// Metrics: the free-run fit %, the 5 s and 30 s horizon fits (higher is better), and the
// absolute errors of the closed-loop criteria (zig-zag overshoots, turning circle's tactical
// diameter; lower is better; a replay that diverged or never reached the criterion counts as an
// infinite error).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "harness/result_row.h"
#include "harness/suite.h"

namespace usvid {

inline constexpr double kVerdictAlpha = 0.05;

struct Standing {
  std::string method;
  double median = 0.0;         // of the method's cell scores
  double mean_rank = 0.0;      // Friedman mean rank (higher: better)
  int cells = 0, failed = 0;   // cells scored, cells whose fit failed
  int runs = 0, diverged = 0;  // test rows scored, of those whose free run diverged
  double p_vs_best = 1.0;      // Holm-adjusted Wilcoxon p against the best
  bool tied_with_best = true;
  bool tied_with_previous = true;  // with the method ranked just above
};

// Two methods head to head, as the suite's "pairs" ask (the mission's GP-SR against
// Eriksen-Breivik): over the cells both have, the median of the paired differences a - b in the
// metric's units (a failed fit or a diverged free run is the worst score of its cell, as in the
// ranking, so a difference may be infinite) and the exact two-sided Wilcoxon signed-rank p,
// not adjusted: it is the one question asked, not one of the ranking's many.
struct PairTest {
  std::string a, b;  // the methods' labels
  int cells = 0;
  double median_difference = 0.0;
  double p = 1.0;
};

struct VerdictEntry {
  std::string vessel, train_maneuver, metric, label;
  bool higher_is_better = true;
  int cells = 0;            // paired cells the test used
  double friedman_p = 1.0;  // 1 with fewer than two methods or cells
  std::vector<Standing> ranking;     // best first
  std::optional<double> ceiling;     // the nominal model's median
  std::vector<std::string> failing;  // methods whose fit failed in every cell
  std::vector<PairTest> pairs;       // the suite's "pairs", where both methods have cells
};

std::vector<VerdictEntry> Verdict(const Suite& suite, const std::vector<ResultRow>& rows);
nlohmann::json VerdictJson(const std::vector<VerdictEntry>& verdict);
// Per vessel and training maneuver a table: metric | ranking | Friedman p | cells | nominal,
// then a line for each of the suite's pairs. The JSON names the ceiling after the nominal
// method (kNominalMethodName).
std::string VerdictMarkdown(const std::vector<VerdictEntry>& verdict);

}  // namespace usvid
