// Regression tracking (usvid compare --baseline PREV/results.json): rows are grouped by vessel,
// training and test maneuver, method and noise; a group is worse when its mean held-out fit
// fell below the baseline's by more than the spread over seeds (the larger standard deviation of
// the two, at least 0.5 points), or its mean fit time grew by more than 50 % and more than three
// such spreads. Groups missing on either side are listed, not judged.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "harness/run_suite.h"

namespace usvid {

struct RegressionReport {
  nlohmann::json groups = nlohmann::json::array();  // every compared group with its verdict
  int worse = 0;
  std::string Markdown() const;
};

// Throws InputError when the baseline is not a results.json (naming the file and field).
RegressionReport CompareWithBaseline(const std::vector<ResultRow>& rows,
                                     const nlohmann::json& baseline, const std::string& file);

}  // namespace usvid
