// usvid identify --method gp --data F.csv (--vessel V | --states u,v,r --inputs a,b)
//                [preprocessing flags] [--operators +,-,*] [--population N] [--generations N]
//                [--max-depth D] [--seed N] [--threads N] --out model.json
// Fits one method and writes model.json (contract section 5).

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <set>

#include "apps/usvid/commands.h"
#include "apps/usvid/preprocess_options.h"
#include "core/csv_dataset.h"
#include "core/error.h"
#include "core/json_file.h"
#include "methods/eb_lr/eb_lr.h"
#include "methods/fossen_ceres/fossen_fit.h"
#include "methods/gp/gp_identify.h"
#include "methods/sindy/sindy.h"
#include "preprocessing/delay_estimation.h"
#include "simulation/segment_error.h"
#include "simulation/vessel_simulator.h"
#include "simulators/odin3dof.h"

namespace usvid {
namespace {

struct IdentifyOptions {
  std::string method;
  std::string data;
  std::string vessel;
  std::vector<std::string> states, inputs;
  PreprocessFlags pre;
  std::string operators = "+,-,*";
  int population = 2000;
  int generations = 50;
  int max_depth = 6;
  double ols_threshold = 0.05;
  std::string fitness = "r2";
  long fit_rows = 4000;
  uint64_t seed = 1;
  int threads = 0;
  std::string fossen_mode = "simulation";
  double segment_s = 10.0;
  bool robust = false;
  std::string out;
};

// fossen-ceres: the parametric odin3dof model, equation error then multiple shooting.
nlohmann::json IdentifyFossen(const IdentifyOptions& o, const Dataset& data,
                              const PreparedData& prepared) {
  fossen::FossenOptions fo;
  fo.segment_s = o.segment_s;
  fo.robust = o.robust;
  fo.threads = o.threads > 0 ? o.threads : 1;
  const fossen::FossenFit eq = fossen::FitEquationError(prepared, fo);
  std::cerr << "usvid identify: equation-error fit: " << eq.termination << '\n';
  fossen::FossenFit fit = eq;
  if (o.fossen_mode == "simulation") {
    fit = fossen::FitSimulationError(prepared, eq.params, fo);
    std::cerr << "usvid identify: simulation-error fit (multiple shooting, " << o.segment_s
              << " s segments): " << fit.termination << '\n';
  }
  nlohmann::json params = nlohmann::json::object(), sd = nlohmann::json::object(),
                 eq_params = nlohmann::json::object();
  for (int i = 0; i < Odin3Dof::kParams; ++i) {
    const std::string name(Odin3Dof::kParamNames[i]);
    params[name] = fit.params[i];
    sd[name] = fit.sd[i];
    eq_params[name] = eq.params[i];
  }
  nlohmann::json refined = nullptr;
  if (prepared.delay_estimate) {
    // The delay to a fraction of a sample: NLopt (DIRECT-L, then Sbplx) on the segmented
    // simulation error of the fitted model on the data as recorded.
    const VesselSimulator& sim = FindVessel("odin3dof");
    const std::vector<double> p(fit.params.begin(), fit.params.end());
    auto cost = [&](const std::vector<double>& d) {
      EffectValues<double> e;
      e.delay_s = d[0];
      return SegmentedSimulationError(sim, p, e, data, {"u", "v", "r"}, o.segment_s);
    };
    const DelayEstimate d = ContinuousDelay(cost, 1, o.pre.max_delay_s, {prepared.delay_s}, 60);
    refined = d.delay_s;
    std::cerr << "usvid identify: delay refined on the simulation error: " << d.delay_s << " s\n";
  }
  return {{"parameters", params},
          {"equations", fossen::Equations(fit.params)},
          {"fossen",
           {{"mode", o.fossen_mode},
            {"segment_s", o.segment_s},
            {"robust", o.robust},
            {"parameter_sd", sd},
            {"covariance_ok", fit.covariance_ok},
            {"termination", fit.termination},
            {"converged", fit.converged},
            {"initial_cost", fit.initial_cost},
            {"final_cost", fit.final_cost},
            {"iterations", fit.iterations},
            {"equation_error_parameters", eq_params},
            {"delay_refined_s", refined}}}};
}

// The vessel's states less `excluded`, in order.
std::vector<std::string> StatesExcept(const VesselInfo& info,
                                      const std::set<std::string>& excluded) {
  std::vector<std::string> out;
  for (const std::string& s : info.states)
    if (!excluded.contains(s)) out.push_back(s);
  return out;
}

// Positions and heading follow from the kinematics and need no equation; the dynamics do not
// depend on them either, except the msd's spring on x. Actuator feedback is left out.
const std::set<std::string> kNotVariables = {"north",        "east",           "psi", "chi", "rpm",
                                             "nozzle_angle", "bucket_position"};

void RunIdentify(const IdentifyOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> states = o.states, variables = o.states, inputs = o.inputs;
  if (!o.vessel.empty()) {
    const VesselInfo& info = FindVessel(o.vessel).Info();
    if (states.empty()) {
      variables = StatesExcept(info, kNotVariables);
      std::set<std::string> no_equation = kNotVariables;
      no_equation.insert("x");
      states = StatesExcept(info, no_equation);
    }
    if (inputs.empty()) inputs = info.inputs;
  }
  if (states.empty() || inputs.empty())
    throw InputError("identify: give --vessel, or --states and --inputs");
  if (o.method == "eb-lr") {
    // The Eriksen-Breivik 2-DOF form: speed U and rate r, driven by thrust and yaw inputs.
    if (!o.vessel.empty() && o.states.empty()) {
      const Actuation& a = FindVessel(o.vessel).Info().actuation;
      if (a.thrust_input < 0)
        throw InputError("--method eb-lr: vessel " + o.vessel + " has no thrust input");
      states = variables = {"U", "r"};
      inputs = {a.input_names[a.thrust_input], a.input_names[a.yaw_input]};
    }
    if (states.size() != 2 || inputs.size() != 2)
      throw InputError("--method eb-lr: needs --states SPEED,RATE and --inputs THRUST,YAW");
  }
  if (o.method == "fossen-ceres" && (states != std::vector<std::string>{"u", "v", "r"} ||
                                     inputs != std::vector<std::string>{"tau_x", "tau_y", "tau_n"}))
    throw InputError(
        "--method fossen-ceres: fits the Fossen 3-DOF model of odin3dof, states "
        "u,v,r and inputs tau_x,tau_y,tau_n (use --vessel odin3dof)");
  if (o.population < 4 || o.generations < 1 || o.max_depth < 2 || o.max_depth > 17)
    throw InputError("identify: --population >= 4, --generations >= 1, --max-depth in [2, 17]");
  if (!(o.ols_threshold >= 0 && o.ols_threshold < 1))
    throw InputError("--ols-threshold: must be in [0, 1)");
  gp::GpOptions gpo;
  gpo.functions = gp::ParseOperators(o.operators);
  gpo.population = o.population;
  gpo.generations = o.generations;
  gpo.max_depth = o.max_depth;
  gpo.ols_threshold = o.ols_threshold;
  gpo.fitness_mse = o.fitness == "mse";
  gpo.fit_rows = o.fit_rows;
  gpo.seed = o.seed;
  gpo.threads = o.threads;
  const PreprocessOptions pre = o.pre.Options();

  const Dataset data = ReadDatasetCsv(o.data);
  const PreparedData prepared = Preprocess(data, variables, inputs, pre);
  for (const std::string& note : prepared.notes) std::cerr << "usvid identify: " << note << '\n';
  nlohmann::json model = {{"method", o.method},
                          {"vessel", o.vessel},
                          {"states", states},
                          {"variables", variables},
                          {"inputs", inputs},
                          {"seed", o.seed},
                          {"preprocessing",
                           {{"delay_s", prepared.delay_s},
                            {"derivative", pre.derivative.Spec()},
                            {"step_breaks", pre.step_breaks},
                            {"notes", prepared.notes}}}};
  if (o.method == "eb-lr") {
    const eb_lr::EbLrIdentification id =
        eb_lr::IdentifyWithEbLr(data, states[0], states[1], inputs[0], inputs[1], {});
    model["parameters"] = id.parameters;
    model["equations"] = id.equations;
    model["eb_lr"] = id.details;
  } else if (o.method == "fossen-ceres") {
    model.update(IdentifyFossen(o, data, prepared));
  } else if (o.method == "sindy") {
    const sindy::SindyIdentification id =
        sindy::IdentifyWithSindy(prepared, states, variables, inputs, sindy::SindyOptions{});
    model["parameters"] = id.parameters;
    model["equations"] = id.equations;
    model["sindy"] = id.details;
  } else {
    const gp::GpIdentification gp = gp::IdentifyWithGp(
        prepared, states, variables, inputs, gpo,
        [](const std::string& state, const gp::GenerationLog& g) {
          std::fprintf(stderr,
                       "usvid identify: %s' generation %d: best r2 %.6f, size %zu, fitness %.6f, "
                       "%.3g node evaluations/s\n",
                       state.c_str(), g.generation, g.best_r2, g.best_size, g.best_fitness,
                       g.node_evals_per_second);
        });
    model["parameters"] = gp.parameters;
    model["equations"] = gp.equations;
    model["gp"] = {{"operators", gp::OperatorList(gpo.functions)},
                   {"population", gpo.population},
                   {"generations", gpo.generations},
                   {"max_depth", gpo.max_depth},
                   {"crossover", gpo.crossover},
                   {"mutation", gpo.mutation},
                   {"ols_threshold", gpo.ols_threshold},
                   {"fitness", o.fitness},
                   {"fit_rows", gpo.fit_rows},
                   {"node_evaluations", gp.node_evaluations},
                   {"equations", gp.details}};
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  model["train"] = {{"data", o.data}, {"samples", prepared.data.rows()}, {"seconds", seconds}};
  WriteJsonFile(o.out, model);
  for (const auto& [state, eq] : model["equations"].items())
    std::cerr << "usvid identify: " << state << "' = " << eq.get<std::string>() << '\n';
  std::cerr << "usvid identify: wrote " << o.out << " (" << seconds << " s)\n";
}

}  // namespace

void AddIdentifyCommand(CLI::App& app) {
  auto o = std::make_shared<IdentifyOptions>();
  CLI::App* cmd = app.add_subcommand("identify", "Fit one identification method to data");
  cmd->add_option("--method", o->method,
                  "gp (GP-SR with orthogonal least squares), sindy (sparse regression, STRidge), "
                  "eb-lr (Eriksen-Breivik 2-DOF regression on step-grid data) or fossen-ceres "
                  "(parametric Fossen 3-DOF of odin3dof, Ceres)")
      ->required()
      ->check(CLI::IsMember({"gp", "sindy", "eb-lr", "fossen-ceres"}));
  cmd->add_option("--data", o->data, "Training data CSV")->required();
  cmd->add_option("--vessel", o->vessel, "Take states and inputs from this simulator");
  cmd->add_option("--states", o->states, "States to find equations for")->delimiter(',');
  cmd->add_option("--inputs", o->inputs, "Input channels")->delimiter(',');
  o->pre.Add(*cmd);
  cmd->add_option("--operators", o->operators,
                  "GP functions: + - * (default, the report's), / abs tanh sin cos exp sqrt");
  cmd->add_option("--population", o->population, "GP population (the report's 2000)");
  cmd->add_option("--generations", o->generations, "Most GP generations");
  cmd->add_option("--max-depth", o->max_depth, "Deepest tree (the report's 6)");
  cmd->add_option("--ols-threshold", o->ols_threshold,
                  "Cut terms whose error reduction ratio is below this (the report's 0.05)");
  cmd->add_option("--fitness", o->fitness, "r2 (with a size penalty) or mse")
      ->check(CLI::IsMember({"r2", "mse"}));
  cmd->add_option("--fit-rows", o->fit_rows, "Rows the search scores on (0: all)");
  cmd->add_option("--seed", o->seed, "Seed of the search");
  cmd->add_option("--threads", o->threads, "OpenMP threads (0: all cores)");
  cmd->add_option("--fit", o->fossen_mode,
                  "fossen-ceres: simulation (multiple shooting, default) or equation error")
      ->check(CLI::IsMember({"simulation", "equation"}));
  cmd->add_option("--segment", o->segment_s, "fossen-ceres: shooting segment length [s]");
  cmd->add_flag("--robust", o->robust, "fossen-ceres: Huber loss");
  cmd->add_option("--out", o->out, "model.json to write")->required();
  cmd->callback([o] { RunIdentify(*o); });
}

}  // namespace usvid
