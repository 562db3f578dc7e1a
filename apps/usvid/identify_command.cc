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
#include "methods/gp/gp_identify.h"
#include "simulation/vessel_simulator.h"

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
  std::string out;
};

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
  const gp::GpIdentification gp = gp::IdentifyWithGp(
      prepared, states, variables, inputs, gpo,
      [](const std::string& state, const gp::GenerationLog& g) {
        std::fprintf(stderr,
                     "usvid identify: %s' generation %d: best r2 %.6f, size %zu, fitness %.6f, "
                     "%.3g node evaluations/s\n",
                     state.c_str(), g.generation, g.best_r2, g.best_size, g.best_fitness,
                     g.node_evals_per_second);
      });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json model = {
      {"method", "gp"},
      {"vessel", o.vessel},
      {"states", states},
      {"variables", variables},
      {"inputs", inputs},
      {"parameters", gp.parameters},
      {"equations", gp.equations},
      {"train", {{"data", o.data}, {"samples", prepared.data.rows()}, {"seconds", seconds}}},
      {"seed", o.seed},
      {"preprocessing",
       {{"delay_s", prepared.delay_s},
        {"derivative", pre.derivative.Spec()},
        {"step_breaks", pre.step_breaks},
        {"notes", prepared.notes}}},
      {"gp",
       {{"operators", gp::OperatorList(gpo.functions)},
        {"population", gpo.population},
        {"generations", gpo.generations},
        {"max_depth", gpo.max_depth},
        {"crossover", gpo.crossover},
        {"mutation", gpo.mutation},
        {"ols_threshold", gpo.ols_threshold},
        {"fitness", o.fitness},
        {"fit_rows", gpo.fit_rows},
        {"node_evaluations", gp.node_evaluations},
        {"equations", gp.details}}}};
  WriteJsonFile(o.out, model);
  for (const auto& [state, eq] : gp.equations.items())
    std::cerr << "usvid identify: " << state << "' = " << eq.get<std::string>() << '\n';
  std::cerr << "usvid identify: wrote " << o.out << " (" << seconds << " s)\n";
}

}  // namespace

void AddIdentifyCommand(CLI::App& app) {
  auto o = std::make_shared<IdentifyOptions>();
  CLI::App* cmd = app.add_subcommand("identify", "Fit one identification method to data");
  cmd->add_option("--method", o->method, "gp (GP-SR with orthogonal least squares)")
      ->required()
      ->check(CLI::IsMember({"gp"}));
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
  cmd->add_option("--out", o->out, "model.json to write")->required();
  cmd->callback([o] { RunIdentify(*o); });
}

}  // namespace usvid
