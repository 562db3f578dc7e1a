// refit's and hybrid's model.json: a vessel's fitted parameters and how the fit went, and the
// refit options a request asks for (methods/refit/refit.h).
#pragma once

#include <nlohmann/json.hpp>

#include "methods/identify_request.h"
#include "methods/refit/refit.h"

namespace usvid {

// Parameter name -> fitted value, every parameter of the vessel.
nlohmann::json RefitParameters(const RefitResult& fit);
// The free parameters, start, ratios to it, segments and the solver's report.
nlohmann::json RefitDetails(const RefitResult& fit, double prior_sd);
// The request's free parameters, segment length and prior; one thread (deterministic).
RefitOptions RefitOptionsFor(const IdentifyRequest& request);

}  // namespace usvid
