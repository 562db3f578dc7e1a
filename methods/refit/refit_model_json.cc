#include "methods/refit/refit_model_json.h"

#include <algorithm>

#include "core/error.h"
#include "methods/identify_request.h"

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

std::vector<OptionSpec> RefitOptionSpecs() {
  const RefitOptions d;
  return {
      ListOption("refit_params", {}, {},
                 "the parameters to fit; none: the vessel's damping group (for kvlcc2 its 17 "
                 "hull coefficients)"),
      NumberOption("segment_s", 0.0, 0, kUnbounded,
                   "shooting segment length [s]; 0: 1.5 hull lengths of travel, at least 10 s"),
      NumberOption("prior_sd", d.prior_sd, 0, kUnbounded,
                   "prior standard deviation of each free parameter, relative to its start",
                   /*min_exclusive=*/true),
      IntegerOption("fit_rows", kCeresFitRows, 0, kUnbounded,
                    "the most rows the Ceres fit uses, spread over a longer record (0: all)"),
      ChoiceOption("record_weights", "rows", {"rows", "equal"},
                   "how the records of a joint fit (--data a.csv,b.csv) weigh: by their rows "
                   "(rows), or each the same (equal)"),
  };
}

RefitOptions RefitOptionsFor(const MethodOptions& o) {
  RefitOptions ro;
  ro.free = o.List("refit_params");
  ro.segment_s = o.Number("segment_s");
  ro.prior_sd = o.Number("prior_sd");
  ro.max_rows = o.Integer("fit_rows");
  ro.equal_records = o.Text("record_weights") == "equal";
  ro.threads = 1;  // deterministic, as for fossen-ceres
  return ro;
}

}  // namespace usvid
