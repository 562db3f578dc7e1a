// The comparison as a person looks at it: per vessel a heat map of held-out fit % (method x test
// maneuver, mean over seeds and noise) and a figure of one held-out run, measured against every
// method's free run; and report.html, one self-contained page with those figures inline (no
// external files) and summary.md's tables.
#pragma once

#include <string>
#include <vector>

#include "harness/run_suite.h"
#include "harness/suite.h"

namespace usvid {

// Writes DIR/fit_<vessel>.svg, DIR/run_<vessel>.svg and DIR/report.html.
void WriteReport(const Suite& suite, const std::vector<ResultRow>& rows, const std::string& summary,
                 const std::string& dir);

}  // namespace usvid
