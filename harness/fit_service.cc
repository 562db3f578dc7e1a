#include "harness/fit_service.h"

#include <algorithm>

#include "core/error.h"
#include "harness/suite_methods.h"
#include "methods/identify.h"
#include "metrics/yaw_bias_calibration.h"
#include "preprocessing/derivative.h"
#include "preprocessing/waterjet_forces.h"
#include "simulation/vessel_simulator.h"

namespace usvid {

const std::vector<OptionSpec>& SharedFitOptions() {
  static const std::vector<OptionSpec> shared = {
      ListOption("states", {}, {}, "the states to fit; none: the vessel's"),
      ListOption("inputs", {}, {}, "the input channels; none: the vessel's (or its jets' forces)"),
      NumberOption("rate", std::nullopt, 0, kUnbounded,
                   "resample the training data to this rate [Hz]; none or 0: the data's own"),
      [] {
        OptionSpec forces = ChoiceOption(
            "forces", "", {"none", "waterjet"},
            "the input map: none (the commands) or waterjet (the jets' forces); unset: "
            "waterjet for a method that takes channels on a vessel that logs its jets");
        forces.default_value = nullptr;
        return forces;
      }(),
      TextOption("derivative", std::nullopt,
                 "how the states' derivatives are computed: sg[:W[:P]], spline[:LAMBDA], "
                 "tv[:ALPHA] or euler[:W]; none: spline"),
  };
  return shared;
}

bool IsSharedFitKey(const std::string& key) {
  return std::ranges::any_of(SharedFitOptions(), [&](const OptionSpec& s) { return s.key == key; });
}

nlohmann::json OwnFitOptions(const nlohmann::json& options) {
  nlohmann::json own = nlohmann::json::object();
  for (const auto& [key, value] : options.items())
    if (!IsSharedFitKey(key)) own[key] = value;
  return own;
}

namespace {

// The input map: the options' "forces" ("none": the commands), else the waterjet forces when
// the vessel logs its jets' states and the method takes inputs as channels (not a vessel model,
// nor the inputs named by hand; eb-lr finds its steady windows where the commands are held).
std::string ForcesFor(const std::string& method, const nlohmann::json& options,
                      const VesselRef& vessel) {
  if (options.contains("forces"))
    return options["forces"] == "none" ? "" : options["forces"].get<std::string>();
  if (vessel.empty() || options.contains("inputs") || !FindSuiteMethod(method).channel_inputs)
    return "";
  return HasWaterjetStates(vessel.Info().states) ? "waterjet" : "";
}

}  // namespace

IdentifyRequest FitRequest(const std::string& method, const nlohmann::json& options,
                           const VesselRef& vessel, uint64_t seed, const PreprocessOptions& base) {
  IdentifyRequest r;
  r.method = method;
  r.vessel = vessel;
  r.seed = seed;
  r.options = OwnFitOptions(options);
  r.preprocess = base;
  r.preprocess.rate_hz = options.value("rate", 0.0);  // resample to this rate [Hz] (0: the data's)
  if (options.contains("derivative"))
    r.preprocess.derivative = DerivativeMethod::Parse(options["derivative"].get<std::string>());
  r.preprocess.forces = ForcesFor(method, options, vessel);
  // A list option, as an array or a comma-separated string.
  auto names = [&](const char* key) {
    const MethodOptions checked =
        ValidateOptions(method, SharedFitOptions(), nlohmann::json{{key, options[key]}}, "options");
    return checked.List(key);
  };
  if (options.contains("states")) r.states = names("states");
  if (options.contains("inputs")) r.inputs = names("inputs");
  return r;
}

nlohmann::json Fit(const Method& method, const Dataset& data, const IdentifyRequest& request,
                   const Logger& log) {
  nlohmann::json model = Identify(method, data, request, log);
  // A closed-loop replay of the training records: metrics/, not the method's own.
  CalibrateRequested(model, data, request.vessel);
  return model;
}

}  // namespace usvid
