// The table of a leave-one-run-out cross-validation (harness/cross_validation.h): summary.md's
// "Leave-one-run-out cross-validation" and results.json's "cross_validation". Per criterion and
// method, each held-out run's value and the mean over the runs with its percentile bootstrap
// interval (harness/bootstrap.h: the runs resampled, kBootstrapResamples, kBootstrapSeed).
//
// Criteria: the free-run fit % (the mean over the states, higher is better), and the absolute
// error of every closed-loop criterion the held-out runs' replays give (closed_loop's
// "<criterion>_error_<unit>", metrics/closed_loop_replay.h; lower is better): the zig-zag's
// first and second overshoots [deg], the turning circle's tactical diameter as a % of the
// measured one, and any other (advance, transfer [m], ...) in its unit. A criterion's runs are
// those whose record gives it. A run whose fit failed or whose free run diverged is missing for
// every criterion of that method, and a replay that gave no value (it diverged, or never
// reached the criterion) for its own: counted as missing, never averaged in, never a NaN. Several
// rows of one run (seeds of a seeded method) are averaged first. A mean over one run has no
// interval.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "harness/bootstrap.h"
#include "harness/result_row.h"
#include "harness/suite.h"

namespace usvid {

struct CrossValidatedMethod {
  std::string method;
  std::map<std::string, double> values;        // run -> value
  std::map<std::string, std::string> missing;  // run -> why: failed, diverged, no value, ...
  BootstrapInterval mean;                      // over `values`
};

struct CrossValidatedCriterion {
  std::string key, label;
  bool higher_is_better = false;
  std::vector<std::string> runs;  // the held-out runs the criterion applies to, in suite order
  std::vector<CrossValidatedMethod> methods;
};

// Empty for a suite that is not cross-validated.
std::vector<CrossValidatedCriterion> CrossValidationTable(const Suite& suite,
                                                          const std::vector<ResultRow>& rows);
nlohmann::json CrossValidationJson(const Suite& suite, const std::vector<ResultRow>& rows);
// "## Leave-one-run-out cross-validation": the means and intervals per method and criterion,
// then per criterion every run's value.
std::string CrossValidationMarkdown(const Suite& suite, const std::vector<ResultRow>& rows);

}  // namespace usvid
