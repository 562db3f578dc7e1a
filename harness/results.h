// The comparison's outputs: results.json (the suite and every row), results.csv (one row per
// fit and test maneuver, the fit % of each state and their mean), and summary.md: per vessel a
// method x test-maneuver table of mean +- sd over seeds and noise levels, per method the
// training x test generalisation matrix, and the maneuver design answer (which training
// maneuver generalises best to the others, per method and vessel). Failed rows are counted and
// listed, never averaged in.
#pragma once

#include <string>
#include <vector>

#include "harness/run_suite.h"
#include "harness/suite.h"

namespace usvid {

nlohmann::json ResultsJson(const Suite& suite, const std::vector<ResultRow>& rows, double seconds);
std::string ResultsCsv(const std::vector<ResultRow>& rows);
std::string SummaryMarkdown(const Suite& suite, const std::vector<ResultRow>& rows, double seconds);

}  // namespace usvid
