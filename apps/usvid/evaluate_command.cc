// usvid evaluate --model model.json --data F.csv[,G.csv,...] [--maneuver zigzag:A/B|turning:A]
//                [--vessel V] [--out DIR]
// Free-runs the model on F's inputs and scores it: metrics.json (on stdout without --out) and,
// with --out, a plot of measured against simulated channels. Several records are each scored on
// their own: metrics.json then lists them under "records", with a summary (the median fit % of
// each state over the records that did not diverge), and the plots are free_run_1.svg, .... With
// --maneuver, the maneuver F records is also re-run closed-loop on the model
// (metrics/closed_loop_replay.h) and its criteria reported beside F's own under "closed_loop"; the
// vessel (actuators, limits) is the model's "vessel" unless --vessel names one.

#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "apps/usvid/commands.h"
#include "apps/usvid/data_file.h"
#include "apps/usvid/preprocess_options.h"
#include "core/atomic_file.h"
#include "core/csv_dataset.h"
#include "core/error.h"
#include "core/json_file.h"
#include "core/model_view.h"
#include "core/records.h"
#include "metrics/closed_loop_replay.h"
#include "metrics/evaluation.h"
#include "plot/figure_grid.h"
#include "simulation/vessel_ref.h"

namespace usvid {
namespace {

struct EvaluateOptions {
  std::string model;
  std::string data;
  std::string actuators;
  std::string maneuver, vessel;
  std::string out;
};

// One record scored: the record, its free run and its metrics.
struct ScoredRecord {
  Dataset data;
  Evaluation evaluation;
};

ScoredRecord EvaluateRecord(const nlohmann::json& model, const EvaluateOptions& o,
                            const std::string& path) {
  ScoredRecord r{ReadDataFile(path, "usvid evaluate"), {}};
  SimulateMissingActuators(r.data, o.actuators);
  try {
    r.evaluation = EvaluateModel(model, r.data);
  } catch (const InputError& err) {
    throw InputError(o.model + " on " + path + ": " + err.what());
  }
  nlohmann::json& metrics = r.evaluation.metrics;
  if (!o.maneuver.empty()) {
    const VesselRef vessel(!o.vessel.empty() ? o.vessel : ModelView(model).Vessel());
    if (vessel.empty())
      throw InputError(o.model +
                       ": --maneuver needs a vessel: the model names none, give --vessel");
    metrics["closed_loop"] =
        ClosedLoopScore(model, vessel, RecordedManeuverSpec(o.maneuver, vessel, r.data), r.data);
  }
  metrics["model"] = o.model;
  metrics["data"] = path;
  return r;
}

// The free run against the measured channels, as an SVG.
void WriteFreeRun(const nlohmann::json& model, const std::string& path, const ScoredRecord& r,
                  const std::string& svg) {
  FigureGrid grid;
  grid.SetTitle("free run of " + ModelView(model).Method("model") + " on " + path)
      .SetXLabel("t", "s");
  int panels = 0;
  for (const std::string& state : r.evaluation.run.channels) {
    if (!r.data.Has(state)) continue;
    ++panels;
    LinePlot p;
    p.SetYLabel(state)
        .AddSeries("measured", r.data.t(), r.data[state], SeriesStyle::Measured())
        .AddSeries("model", r.data.t(), r.evaluation.run.simulated[state]);
    grid.Add(std::move(p));
  }
  grid.WriteSvg(svg, 1000, 260 * panels + 80);
}

// Several records' metrics, each scored on its own (a free run never crosses from one into
// the next), in order, and per state the median fit % over the records that did not diverge.
nlohmann::json SeveralRecordsJson(const std::string& model_path,
                                  const std::vector<ScoredRecord>& scored) {
  nlohmann::json records = nlohmann::json::array();
  std::map<std::string, std::vector<double>> fits;
  int diverged = 0;
  for (const ScoredRecord& r : scored) {
    const nlohmann::json& m = r.evaluation.metrics;
    records.push_back(m);
    if (m.value("diverged", false)) {
      ++diverged;
      continue;
    }
    for (const auto& [state, c] : m.at("channels").items())
      if (c.contains("fit_percent") && c.at("fit_percent").is_number())
        fits[state].push_back(c.at("fit_percent").get<double>());
  }
  nlohmann::json median = nlohmann::json::object();
  for (auto& [state, v] : fits) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    median[state] = n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  }
  return {{"model", model_path},
          {"records", records},
          {"summary",
           {{"records", records.size()}, {"diverged", diverged}, {"median_fit_percent", median}}}};
}

void RunEvaluate(const EvaluateOptions& o) {
  const nlohmann::json model = ReadJsonFile(o.model);
  if (!model.is_object()) throw InputError(o.model + ": expected a JSON object");
  const std::vector<std::string> paths = RecordList(o.data, "usvid evaluate: --data");
  if (paths.size() > 1 && !o.maneuver.empty())
    throw InputError(
        "usvid evaluate: --maneuver names the maneuver of one record; give one "
        "--data file with it, not " +
        std::to_string(paths.size()));
  // Every record scored before anything is written: a bad one leaves no output behind.
  std::vector<ScoredRecord> scored;
  for (const std::string& path : paths) scored.push_back(EvaluateRecord(model, o, path));
  const bool several = paths.size() > 1;
  const nlohmann::json metrics =
      several ? SeveralRecordsJson(o.model, scored) : scored.front().evaluation.metrics;
  if (o.out.empty()) {
    std::cout << metrics.dump(2) << '\n';
    return;
  }
  EnsureOutputDirectory(o.out);
  for (size_t i = 0; i < paths.size(); ++i)
    WriteFreeRun(model, paths[i], scored[i],
                 o.out + (several ? "/free_run_" + std::to_string(i + 1) + ".svg"
                                  : std::string("/free_run.svg")));
  WriteJsonFile(o.out + "/metrics.json", metrics);
  std::cerr << "usvid evaluate: wrote " << o.out << "/metrics.json and "
            << (several ? "free_run_1.svg .. free_run_" + std::to_string(paths.size()) + ".svg"
                        : std::string("free_run.svg"))
            << "\n";
}

}  // namespace

void AddEvaluateCommand(CLI::App& app) {
  auto o = std::make_shared<EvaluateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "evaluate", "Free-run a model on data's inputs and score it (fit %, NRMSE, divergence)");
  cmd->add_option("--model", o->model, "model.json from usvid identify")->required();
  cmd->add_option("--data", o->data,
                  "Data CSV to score on, or several (a.csv,b.csv,...) each scored on its own")
      ->required();
  cmd->add_option("--actuators", o->actuators,
                  "actuators.json from usvid actuators: actuator states the log lacks are "
                  "simulated from its commands");
  cmd->add_option("--maneuver", o->maneuver,
                  "The maneuver the data record (zigzag:A/B or turning:A, A in starboard-positive "
                  "degrees; zigzag or turning alone: the angle and side read from the record): "
                  "re-run closed-loop on the model, its criteria beside the data's");
  cmd->add_option("--vessel", o->vessel,
                  "The vessel whose actuators the replay uses (default: "
                  "the model's)");
  cmd->add_option("--out", o->out, "Directory for metrics.json and plots (else stdout)");
  cmd->callback([o] { RunEvaluate(*o); });
}

}  // namespace usvid
