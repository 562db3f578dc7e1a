// `refit`: a registered vessel's own coefficients fitted by multiple shooting
// (methods/refit/refit.h), registered in methods/method_list.h.
#include "core/error.h"
#include "methods/method.h"
#include "methods/refit/refit.h"
#include "methods/refit/refit_model_json.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

// refit: the vessel's own coefficients (methods/refit/refit.h); a vessel model, no equations.
nlohmann::json IdentifyRefit(const Dataset& data, const IdentifyRequest& o,
                             const MethodOptions& method_options, const Logger& log) {
  if (o.vessel.empty()) throw InputError("--method refit: needs --vessel");
  const VesselInfo& info = o.vessel.Info();
  const RefitOptions options = RefitOptionsFor(method_options);
  const RefitResult fit = RefitVessel(
      o.vessel, data, o.start_params.empty() ? info.default_params : o.start_params, options);
  const bool spread = options.max_rows > 0 && data.rows() > options.max_rows;
  Log(log, "refit of " + std::to_string(fit.free.size()) + " parameters on " +
               std::to_string(fit.segments) + " segments" +
               (spread ? " spread over the record (--fit-rows)" : "") + ": " + fit.termination);
  return {{"method", o.method},
          {"vessel", o.vessel.Name()},
          {"states", fit.channels},
          {"inputs", info.inputs},
          {"parameters", RefitParameters(fit)},
          {o.method, RefitDetails(fit, options.prior_sd)},
          {"train", {{"data", o.data_name}, {"samples", data.rows()}, {"seconds", fit.seconds}}}};
}

}  // namespace

Method RefitMethod() {
  Method m;
  m.name = std::string(kRefitMethodName);
  m.summary = "the --vessel's own coefficients, Ceres multiple shooting";
  m.options = RefitOptionSpecs();
  m.identify = IdentifyRefit;
  m.relative_cost =
      20.0;  // multiple shooting through the vessel: about GP's time on a vessel's runs
  return m;
}

}  // namespace usvid
