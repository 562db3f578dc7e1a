// Regression tracking (usvid compare --baseline PREV/results.json): did the held-out fit or the
// fit time of a (vessel, method) get worse since the baseline run?
//
// Why paired and rank-based: a suite runs every cell (training maneuver, test maneuver, noise,
// seed) once, with 2 or 3 seeds. A mean over 3 seeds against their spread is neither robust (one
// diverged free run moves it anywhere) nor a test (3 values cannot show a difference). The same
// cell in both runs is a pair, in which what differs between cells (maneuver, noise, seed)
// cancels, and a (vessel, method) has enough pairs for a test (the default suite: 3 train x 3 test
// x 2 noise x 3 seeds = 54). Held-out fits are heavy-tailed (a diverged run scores -inf), so the
// statistics are medians and ranks (metrics/rank_tests.h): no clamping, no normality.
//
// - Cells pair on (vessel, train_maneuver, test_maneuver, method, noise, seed); a key that repeats
//   pairs in order of appearance. Cells on one side only are counted (only_now, only_baseline),
//   not judged.
// - Both "ok": d = fit_now - fit_baseline of mean_fit_percent, in points (d = 0 when equal, so
//   -inf against -inf is no change). A NaN fit, or a null one in the baseline (JSON cannot hold
//   -inf; a fit % is at most 100), counts as -inf: the worst, as a diverged run.
// - Failed now, ok in the baseline: newly failing, listed; the group is "worse fit" whatever its
//   pairs say. Ok now, failed before: newly_ok. Failed on both sides: failing_both.
// - Per group (vessel, method): medians of both sides over the paired cells, the median and
//   quartiles of d, the two-sided Wilcoxon signed-rank p of the pairs (zero differences dropped),
//   and that p Holm-adjusted over every group of the report with at least one pair.
// - Fit time: one pair per fit (the test maneuvers of a fit share its fit_seconds), the same
//   signed-rank test, Holm-adjusted over the groups as a family of its own.
// - Verdict, first that applies:
//   "worse fit": newly failing cells, or median d < -0.5 points at adjusted p < 0.05;
//   "slower": median fit_seconds grew by more than 50 %, at adjusted p < 0.05 of the paired
//     fit times (at least 6 of them differing);
//   "not in the baseline" / "not in this run": no cell of the group on the other side;
//   "too few pairs to test": no pair, or 1 to 5 pairs that differ (with n <= 5 nonzero pairs no
//     two-sided p reaches 0.05: the smallest is 2 / 2^5); the medians are still given;
//   "better fit": median d > +0.5 points at adjusted p < 0.05;
//   "same": otherwise, including every pair identical, and every cell failing on both sides.
//   `worse` counts "worse fit" and "slower".
//
// Group JSON: vessel, method, pairs, nonzero_pairs, median_fit_percent,
// baseline_median_fit_percent, median_difference, difference_q1, difference_q3, p_value,
// p_adjusted, newly_failing (count), newly_failing_cells, newly_ok, failing_both, only_now,
// only_baseline, fit_seconds {pairs, median, baseline_median, p_value, p_adjusted}, verdict.
// Numbers that do not exist (no pairs) or are not finite are null.
//
// Throws InputError when the baseline is not a results.json: no "rows" array, or a row without a
// field it needs or with the wrong type (naming the file, the row and the field).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "harness/result_row.h"

namespace usvid {

struct RegressionReport {
  nlohmann::json groups = nlohmann::json::array();  // every compared group with its verdict
  int worse = 0;                                    // groups "worse fit" or "slower"
  // The groups that are not "same", worst first, the newly failing cells and how the test works.
  std::string Markdown() const;
};

RegressionReport CompareWithBaseline(const std::vector<ResultRow>& rows,
                                     const nlohmann::json& baseline, const std::string& file);

}  // namespace usvid
