// refit's and hybrid's model.json: a vessel's fitted parameters and how the fit went, and the
// refit options a request asks for (methods/refit/refit.h).
#pragma once

#include <nlohmann/json.hpp>

#include <vector>

#include "methods/method_options.h"
#include "methods/refit/refit.h"

namespace usvid {

// Parameter name -> fitted value, every parameter of the vessel.
nlohmann::json RefitParameters(const RefitResult& fit);
// The free parameters, start, ratios to it, segments and the solver's report.
nlohmann::json RefitDetails(const RefitResult& fit, double prior_sd);
// The options refit declares, and hybrid with it: refit_params, segment_s, prior_sd, fit_rows.
std::vector<OptionSpec> RefitOptionSpecs();
// Those options as the fit's: free parameters, segment length, prior and rows; one thread
// (deterministic).
RefitOptions RefitOptionsFor(const MethodOptions& options);

}  // namespace usvid
