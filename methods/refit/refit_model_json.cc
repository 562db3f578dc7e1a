#include "methods/refit/refit_model_json.h"

#include <algorithm>

#include "core/error.h"

namespace usvid {

nlohmann::json RefitParameters(const RefitResult& fit) {
  nlohmann::json params = nlohmann::json::object();
  for (size_t i = 0; i < fit.names.size(); ++i) params[fit.names[i]] = fit.params[i];
  return params;
}

nlohmann::json RefitDetails(const RefitResult& fit, double prior_sd) {
  nlohmann::json start = nlohmann::json::object(), ratio = nlohmann::json::object();
  for (size_t i = 0; i < fit.names.size(); ++i) start[fit.names[i]] = fit.start[i];
  for (const std::string& n : fit.free) {
    const size_t i = std::find(fit.names.begin(), fit.names.end(), n) - fit.names.begin();
    ratio[n] = fit.start[i] != 0.0 ? fit.params[i] / fit.start[i] : fit.params[i];
  }
  return {{"free", fit.free},
          {"ratio_to_start", ratio},
          {"start", start},
          {"segment_s", fit.segment_s},
          {"prior_sd", prior_sd},
          {"segments", fit.segments},
          {"residuals", fit.residuals},
          {"termination", fit.termination},
          {"converged", fit.converged},
          {"initial_cost", fit.initial_cost},
          {"final_cost", fit.final_cost},
          {"iterations", fit.iterations}};
}

RefitOptions RefitOptionsFor(const IdentifyRequest& o) {
  RefitOptions ro;
  ro.free = o.refit_params;
  ro.segment_s = o.segment_s;
  ro.prior_sd = o.prior_sd;
  ro.max_rows = o.fit_rows.value_or(kCeresFitRows);
  if (ro.max_rows < 0) throw InputError("--fit-rows: must be 0 (all) or more");
  ro.threads = 1;  // deterministic, as for fossen-ceres
  return ro;
}

}  // namespace usvid
