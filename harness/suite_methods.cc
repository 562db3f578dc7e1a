#include "harness/suite_methods.h"

#include <algorithm>

#include "core/error.h"
#include "diagnosis/diagnose.h"
#include "diagnosis/diagnosis_json.h"
#include "harness/external_method.h"
#include "methods/channel_fit.h"
#include "methods/registry.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

nlohmann::json DiagnosedModel(const Dataset& train, const IdentifyRequest& request,
                              const MethodOptions& o, const Logger&) {
  if (request.vessel.empty()) throw InputError("diagnose: needs a vessel");
  diagnosis::DiagnoseOptions options;
  options.split.segment_s = o.Number("segment_s");
  options.split.max_fit_rows = o.Integer("fit_rows");
  options.max_causes = static_cast<int>(o.Integer("causes"));
  options.discover = false;  // proposals are for a person to read, not part of the model
  const diagnosis::Diagnosis d =
      diagnosis::Diagnose(train, request.vessel, request.vessel.Info().default_params, options);
  nlohmann::json model = diagnosis::ExtendedModelJson(d);
  model["states"] = d.channels;
  return model;
}

Method DiagnoseSuiteMethod() {
  Method m;
  m.name = std::string(kDiagnoseMethod);
  m.summary = "the nominal vessel extended by the causes usvid diagnose names (suites only)";
  const diagnosis::DiagnoseOptions d;
  m.options = {
      IntegerOption("causes", d.max_causes, 0, 100, "most causes added to the nominal vessel"),
      NumberOption("segment_s", d.split.segment_s, 0, kUnbounded,
                   "shooting segment length [s]; 0: 1.5 hull lengths of travel, at least 10 s"),
      IntegerOption("fit_rows", d.split.max_fit_rows, 0, kUnbounded,
                    "most rows each candidate effect is fitted on (the training part's last) and "
                    "scored on (the held-out part's first); 0: every row"),
  };
  m.identify = DiagnosedModel;
  m.relative_cost = 100.0;  // a fit per candidate effect: 62 s on Esso Osaka's runs, GP 18
  m.named_channels = false;  // the vessel's channels, the record as it is
  m.preprocessed = false;
  return m;
}

// The command's channels: the request's, else the vessel's.
nlohmann::json ExternalModel(const Dataset& train, const IdentifyRequest& request,
                             const MethodOptions& o, const Logger&) {
  ExternalCommand command;
  command.name = o.Text("name");
  command.command = o.List("command");
  command.timeout_s = o.Number("timeout_s");
  const Channels channels = DefaultChannels(request);
  return IdentifyExternal(command, train, channels.states, channels.inputs);
}

Method ExternalSuiteMethod() {
  Method m;
  m.name = std::string(kExternalMethod);
  m.summary = "a command outside usvid, fitted like any other row (suites only)";
  const ExternalCommand d;
  m.options = {
      TextOption("name", std::nullopt, "the row's label; not a usvid method's name (required)"),
      ListOption("command", {}, {},
                 "the program and its first arguments; usvid adds --data, --states, --inputs "
                 "and --out (required)"),
      NumberOption("timeout_s", d.timeout_s, 0, kUnbounded,
                   "seconds before the command and its children are killed",
                   /*min_exclusive=*/true),
  };
  m.identify = ExternalModel;
  m.preprocessed = false;  // the command prepares the record itself
  return m;
}

}  // namespace

const std::vector<Method>& SuiteMethods() {
  static const std::vector<Method> methods = [] {
    std::vector<Method> all = Methods();
    all.push_back(DiagnoseSuiteMethod());
    all.push_back(ExternalSuiteMethod());
    return all;
  }();
  return methods;
}

const Method& FindSuiteMethod(std::string_view name) {
  const auto& all = SuiteMethods();
  const auto it = std::ranges::find_if(all, [&](const Method& m) { return m.name == name; });
  if (it == all.end()) {
    std::string known;
    for (const Method& m : all) known += (known.empty() ? "" : ", ") + m.name;
    throw InputError("unknown method '" + std::string(name) + "' (known: " + known + ")");
  }
  return *it;
}

}  // namespace usvid
