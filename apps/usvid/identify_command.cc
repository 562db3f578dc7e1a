// usvid identify --method gp --data F.csv (--vessel V | --states u,v,r --inputs a,b)
//                [preprocessing flags] [--preset default|report] [--operators +,-,*]
//                [--population N] [--generations N] [--max-depth D] [--ols-threshold E]
//                [--validation-fraction F] [--horizon S] [--constant-iterations N] [--restarts N]
//                [--seed N] [--threads N] --out model.json
// Fits one method and writes model.json (docs/data.md#modeljson).

#include <iostream>
#include <memory>

#include "apps/usvid/commands.h"
#include "apps/usvid/data_file.h"
#include "apps/usvid/preprocess_options.h"
#include "core/atomic_file.h"
#include "core/csv_dataset.h"
#include "core/error.h"
#include "core/json_file.h"
#include "core/parse_number.h"
#include "methods/gp/gp_identify.h"
#include "methods/gp/search.h"
#include "methods/identify.h"
#include "methods/regime_features.h"
#include "methods/registry.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

struct IdentifyOptions {
  IdentifyRequest request;
  std::string data;
  std::string params;
  PreprocessFlags pre;
  std::string out;
};

void RunIdentify(const IdentifyOptions& o) {
  CheckOutputFile(o.out);
  if (o.request.fit_rows && *o.request.fit_rows < 0)
    throw InputError("--fit-rows: must be 0 (all) or more");
  IdentifyRequest r = o.request;
  r.preprocess = o.pre.Options();
  r.data_name = o.data;
  if (!o.params.empty()) {
    if (r.vessel.empty()) throw InputError("--params: needs --vessel");
    r.start_params = FindVessel(r.vessel).Info().ParamsFromFile(o.params);
  }
  Dataset data = ReadDataFile(o.data, "usvid identify");
  SimulateMissingActuators(data, o.pre.actuators);
  const nlohmann::json model = Identify(std::move(data), r, [](const std::string& line) {
    std::cerr << "usvid identify: " << line << '\n';
  });
  WriteJsonFile(o.out, model);
  if (model.contains("equations"))
    for (const auto& [state, eq] : model.at("equations").items())
      std::cerr << "usvid identify: " << state << "' = " << eq.get<std::string>() << '\n';
  std::cerr << "usvid identify: wrote " << o.out << " (" << model["train"]["seconds"].get<double>()
            << " s)\n";
}

}  // namespace

void AddIdentifyCommand(CLI::App& app) {
  auto o = std::make_shared<IdentifyOptions>();
  CLI::App* cmd = app.add_subcommand("identify", "Fit one identification method to data");
  std::string methods_help;
  std::vector<std::string> names;
  for (const Method& m : Methods()) {
    methods_help += (methods_help.empty() ? "" : "; ") + m.name + " (" + m.summary + ")";
    names.push_back(m.name);
  }
  cmd->add_option("--method", o->request.method, methods_help)
      ->required()
      ->check(CLI::IsMember(names));
  cmd->add_option("--data", o->data, "Training data CSV")->required();
  cmd->add_option("--vessel", o->request.vessel, "Take states and inputs from this simulator");
  cmd->add_option("--states", o->request.states, "States to find equations for")->delimiter(',');
  cmd->add_option("--inputs", o->request.inputs, "Input channels")->delimiter(',');
  o->pre.Add(*cmd);
  cmd->add_option("--preset", o->request.preset,
                  "gp: default (terms chosen by held-out error, constant optimisation, restarts, "
                  "the model chosen by short-horizon simulation) or report (the reference "
                  "report's Table 3.1 exactly); the options below override it")
      ->check(CLI::IsMember({"default", "report"}));
  cmd->add_option("--operators", o->request.operators,
                  "GP functions: + - * (default, the report's), / abs tanh sin cos exp sqrt");
  cmd->add_option("--features", o->request.features,
                  "gp, sindy: regime features among the variables: auto (hinges when the vessel "
                  "has a length and the record crosses a regime boundary), hinges (the Froude "
                  "number Fn and abs(Fn - k) at quantiles of the record's Fn: 4 for gp, 8 for "
                  "sindy), froude (Fn "
                  "alone), none")
      ->check(CLI::IsMember({"auto", "hinges", "froude", "none"}));
  // GP's defaults are its options' (methods/gp/search.h, gp_identify.h), not spelled here.
  const gp::GpOptions gp_defaults;
  const gp::GpIdentifyOptions gp_identify_defaults;
  auto n = [](auto v) { return FormatNumber(static_cast<double>(v)); };
  cmd->add_option("--population", o->request.population,
                  "GP population (" + n(gp_defaults.population) + ")");
  cmd->add_option("--generations", o->request.generations,
                  "Most GP generations (" + n(gp_defaults.generations) + ")");
  cmd->add_option("--max-depth", o->request.max_depth,
                  "Deepest tree (" + n(gp_defaults.max_depth) + ")");
  cmd->add_option("--ols-threshold", o->request.ols_threshold,
                  "Cut terms whose error reduction ratio is below this (the report's 0.05; "
                  "default: the number of terms chosen by held-out error)");
  cmd->add_option("--validation-fraction", o->request.validation_fraction,
                  "gp: the last share of the record, in [0, 0.5], on which the model is chosen "
                  "among the Pareto candidates by short-horizon simulation (" +
                      n(gp_identify_defaults.validation_fraction) + "; 0: none)");
  cmd->add_option("--horizon", o->request.horizon_s,
                  "gp: seconds of each short-horizon simulation that chooses the model and "
                  "refits its weights (" +
                      n(gp_identify_defaults.horizon_s) + "; " + n(kRegimeHorizonS) +
                      " on a record with regime features)");
  cmd->add_option("--constant-iterations", o->request.constant_iterations,
                  "gp: Levenberg-Marquardt iterations on the constants inside terms, per elite "
                  "(" +
                      n(gp_defaults.constant_iterations) + "; 0: none)");
  cmd->add_option(
      "--restarts", o->request.restarts,
      "gp: restarts on stagnation before the search stops (" + n(gp_defaults.restarts) + ")");
  cmd->add_option("--fitness", o->request.fitness, "r2 (with a size penalty) or mse")
      ->check(CLI::IsMember({"r2", "mse"}));
  cmd->add_option("--fit-rows", o->request.fit_rows,
                  "gp: rows the search scores on (" + n(gp_defaults.fit_rows) +
                      "); fossen-ceres, refit, hybrid: the most rows the Ceres fits use, spread "
                      "over a longer record (" +
                      n(kCeresFitRows) + "); 0: all");
  cmd->add_option("--seed", o->request.seed, "Seed of the search");
  cmd->add_option("--threads", o->request.threads, "OpenMP threads (0: all cores)");
  cmd->add_option("--fit", o->request.fit_mode,
                  "fossen-ceres: simulation (multiple shooting, default) or equation error; gp: "
                  "the chosen terms' weights by equation error, then by short-horizon "
                  "simulation error (simulation, default), or by equation error alone")
      ->check(CLI::IsMember({"simulation", "equation"}));
  cmd->add_option("--segment", o->request.segment_s,
                  "fossen-ceres, refit, hybrid, nomoto: shooting segment length [s] (default: "
                  "fossen-ceres 10 s, nomoto 30 s, refit 1.5 hull lengths of travel, at least "
                  "10 s)");
  cmd->add_option("--refit-params", o->request.refit_params,
                  "refit, hybrid: the parameters to fit (default: the vessel's damping group, for "
                  "kvlcc2 its 17 hull coefficients)")
      ->delimiter(',');
  cmd->add_option("--prior-sd", o->request.prior_sd,
                  "refit, hybrid: prior standard deviation of each free parameter, relative to its "
                  "start")
      ->capture_default_str();
  cmd->add_option("--max-terms", o->request.hybrid_terms,
                  "hybrid: most missing terms to add to the vessel (default 3)")
      ->check(CLI::Range(0, 6));
  cmd->add_option("--params", o->params,
                  "refit, hybrid, nominal: starting parameters (JSON of name: value, or a model's "
                  "\"parameters\"); default the vessel's");
  cmd->add_flag("--robust", o->request.robust, "fossen-ceres: Huber loss");
  cmd->add_option("--out", o->out, "model.json to write")->required();
  cmd->callback([o] { RunIdentify(*o); });
}

}  // namespace usvid
