// usvid evaluate --model model.json --data F.csv [--maneuver zigzag:A/B|turning:A]
//                [--vessel V] [--out DIR]
// Free-runs the model on F's inputs and scores it: metrics.json (on stdout without --out) and,
// with --out, a plot of measured against simulated channels. With --maneuver, the maneuver F
// records is also re-run closed-loop on the model (metrics/closed_loop_replay.h) and its
// criteria reported beside F's own under "closed_loop"; the vessel (actuators, limits) is the
// model's "vessel" unless --vessel names one.

#include <iostream>
#include <memory>

#include "apps/usvid/commands.h"
#include "apps/usvid/data_file.h"
#include "apps/usvid/preprocess_options.h"
#include "core/atomic_file.h"
#include "core/csv_dataset.h"
#include "core/error.h"
#include "core/json_file.h"
#include "metrics/closed_loop_replay.h"
#include "metrics/evaluation.h"
#include "simulation/vessel_simulator.h"
#include "plot/figure_grid.h"

namespace usvid {
namespace {

struct EvaluateOptions {
  std::string model;
  std::string data;
  std::string actuators;
  std::string maneuver, vessel;
  std::string out;
};

void RunEvaluate(const EvaluateOptions& o) {
  const nlohmann::json model = ReadJsonFile(o.model);
  if (!model.is_object()) throw InputError(o.model + ": expected a JSON object");
  Dataset data = ReadDataFile(o.data, "usvid evaluate");
  SimulateMissingActuators(data, o.actuators);
  Evaluation e;
  try {
    e = EvaluateModel(model, data);
  } catch (const InputError& err) {
    throw InputError(o.model + " on " + o.data + ": " + err.what());
  }
  if (!o.maneuver.empty()) {
    std::string vessel = o.vessel;
    if (vessel.empty() && model.contains("vessel") && model["vessel"].is_string())
      vessel = model["vessel"].get<std::string>();
    if (vessel.empty())
      throw InputError(o.model + ": --maneuver needs a vessel: the model names none, give --vessel");
    FindVessel(vessel);  // throws for an unknown name
    e.metrics["closed_loop"] = ClosedLoopScore(model, vessel, o.maneuver, data);
  }
  e.metrics["model"] = o.model;
  e.metrics["data"] = o.data;
  if (o.out.empty()) {
    std::cout << e.metrics.dump(2) << '\n';
    return;
  }
  EnsureOutputDirectory(o.out);
  FigureGrid grid;
  grid.SetTitle("free run of " + model.value("method", std::string("model")) + " on " + o.data)
      .SetXLabel("t", "s");
  int panels = 0;
  for (const std::string& state : e.run.channels) {
    if (!data.Has(state)) continue;
    ++panels;
    LinePlot p;
    p.SetYLabel(state)
        .AddSeries("measured", data.t(), data[state])
        .AddSeries("model", data.t(), e.run.simulated[state]);
    grid.Add(std::move(p));
  }
  grid.WriteSvg(o.out + "/free_run.svg", 1000, 260 * panels + 80);
  WriteJsonFile(o.out + "/metrics.json", e.metrics);
  std::cerr << "usvid evaluate: wrote " << o.out << "/metrics.json and free_run.svg\n";
}

}  // namespace

void AddEvaluateCommand(CLI::App& app) {
  auto o = std::make_shared<EvaluateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "evaluate", "Free-run a model on data's inputs and score it (fit %, NRMSE, divergence)");
  cmd->add_option("--model", o->model, "model.json from usvid identify")->required();
  cmd->add_option("--data", o->data, "Data CSV to score on")->required();
  cmd->add_option("--actuators", o->actuators,
                  "actuators.json from usvid actuators: actuator states the log lacks are "
                  "simulated from its commands");
  cmd->add_option("--maneuver", o->maneuver,
                  "The maneuver the data record (zigzag:A/B or turning:A, A in starboard-positive "
                  "degrees): re-run closed-loop on the model, its criteria beside the data's");
  cmd->add_option("--vessel", o->vessel, "The vessel whose actuators the replay uses (default: "
                  "the model's)");
  cmd->add_option("--out", o->out, "Directory for metrics.json and plots (else stdout)");
  cmd->callback([o] { RunEvaluate(*o); });
}

}  // namespace usvid
