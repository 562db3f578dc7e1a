// usvid simulate --vessel V --maneuver M [--effect NAME=VALUE[@INPUT] ...] [--noise S] [--seed N]
//                [--rates imu=50,gps=5,jet=10] [--wind SPEED[:FROM_DEG]]
//                [--gusts SPEED[:FROM_DEG]] [--waves HS[:TP[:FROM_DEG]]] [--dropouts gps=0.05,...]
//                [--logged wind,current] --out F.csv
//                                                                   (writes F.truth.json too)
// usvid simulate --vessel V --inputs IN.csv [--dt H] --out F.csv

#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <random>

#include "apps/usvid/commands.h"
#include "apps/usvid/data_file.h"
#include "core/atomic_file.h"
#include "core/csv_dataset.h"
#include "core/error.h"
#include "core/json_file.h"
#include "core/parse_number.h"
#include "maneuvers/maneuver_factory.h"
#include "maneuvers/true_wind.h"
#include "simulation/logged_disturbances.h"
#include "simulation/simulate_record.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

struct SimulateOptions {
  std::string vessel;
  std::string maneuver;
  std::string inputs;
  std::vector<std::string> effects;
  double noise = 0.0;
  uint64_t seed = 1;
  std::vector<std::string> rates;
  std::string params;
  double duration = 0.0;
  std::optional<double> cruise;
  double dt = 0.01;
  double rate_hz = 20.0;
  std::string integrator = "rk4";
  std::string wind;
  std::string gusts;
  std::string waves;
  std::vector<std::string> dropouts;
  std::vector<std::string> logged;
  std::string out;
};

// --wind SPEED[:FROM_DEG]: the mean true wind; without a direction, one drawn from the seed.
TrueWind ParseWind(const std::string& text, uint64_t seed) {
  const std::string where = "--wind '" + text + "': ";
  const auto colon = text.find(':');
  auto number = [&](const std::string& t) {
    const ParsedNumber p = ParseNumber(t);
    if (p.status != NumberStatus::kOk) throw InputError(where + DescribeNumberStatus(p.status, t));
    return p.value;
  };
  TrueWind w;
  w.speed = number(text.substr(0, colon));
  if (!(w.speed >= 0.0 && w.speed <= 60.0))
    throw InputError(where + "the speed must be in [0, 60] m/s");
  if (colon != std::string::npos) {
    w.from_rad = number(text.substr(colon + 1)) * std::numbers::pi / 180.0;
  } else {
    std::mt19937_64 rng(seed ^ 0x3A1Dull);
    w.from_rad = std::uniform_real_distribution<double>(0.0, 2.0 * std::numbers::pi)(rng);
  }
  return w;
}

// F.csv -> F.truth.json
std::string TruthPath(const std::string& out) {
  const auto dot = out.rfind('.');
  const auto slash = out.rfind('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_ext ? out.substr(0, dot) : out) + ".truth.json";
}

// The effects the run hides: a model file's (--params, a diagnose model.json), and --effect items,
// which replace those of the same kind; wind only on a vessel with a wind model.
std::vector<Effect> SimulatedEffects(const SimulateOptions& o, const VesselInfo& info) {
  const std::vector<Effect> effects =
      MergeEffects(o.params.empty() ? std::vector<Effect>{} : EffectsOfFile(o.params),
                   ParseEffects(o.effects, o.seed));
  for (const Effect& e : effects)
    if (e.kind == EffectKind::kWind && !info.wind_body)
      throw InputError("--effect wind: vessel " + info.name +
                       " has no wind model (a vessel file with a wind section has)");
  return effects;
}

void RunSimulate(const SimulateOptions& o) {
  if (o.maneuver.empty() == o.inputs.empty())
    throw InputError("simulate: give exactly one of --maneuver and --inputs");
  if (!(o.dt > 0) || !(o.rate_hz > 0)) throw InputError("--dt and --rate: must be positive");
  CheckOutputFile(o.out);
  RecordRecipe recipe;
  recipe.vessel = o.vessel;
  const VesselInfo& info = recipe.vessel.Info();
  recipe.maneuver = o.maneuver;
  recipe.duration_s = o.duration;
  recipe.cruise = o.cruise;
  recipe.effects = SimulatedEffects(o, info);
  CheckLoggedDisturbances(o.logged, !o.gusts.empty(), recipe.effects, "--logged");
  if (!o.params.empty()) recipe.params = info.ParamsFromFile(o.params);
  recipe.run.dt = o.dt;
  recipe.run.rate_hz = o.rate_hz;
  recipe.run.integrator = o.integrator == "dopri" ? Integrator::kDormandPrince : Integrator::kRk4;
  if (!o.wind.empty()) recipe.wind = ParseWind(o.wind, o.seed);
  recipe.gusts = o.gusts;
  recipe.gusts_where = "--gusts '" + o.gusts + "'";
  recipe.logged = o.logged;
  recipe.sensors = {o.waves, o.noise, o.rates, o.dropouts};
  recipe.seed = o.seed;
  Dataset inputs;
  if (!o.inputs.empty()) {
    if (!o.wind.empty() || !o.gusts.empty())
      throw InputError(
          "simulate: --wind and --gusts make a maneuver's wind; with --inputs the file's "
          "wind_speed and wind_direction columns are the wind");
    inputs = ReadDataFile(o.inputs, "usvid simulate");
    recipe.inputs = &inputs;
  }
  SimulatedRecord record = SimulateRecord(
      recipe, [](const std::string& line) { std::cerr << "usvid simulate: " << line << '\n'; });
  if (record.diverged)
    throw InputError("simulate: the " + info.name + " simulation diverged at t = " +
                     std::to_string(record.diverged_at_s) + " s (check --params and inputs)");
  if (!o.inputs.empty()) record.truth["inputs_file"] = o.inputs;
  WriteDatasetCsv(o.out, record.data);
  WriteJsonFile(TruthPath(o.out), record.truth);
  std::cerr << "usvid simulate: wrote " << o.out << " (" << record.data.rows() << " rows, "
            << record.data.duration() << " s) and " << TruthPath(o.out) << '\n';
}

}  // namespace

void AddSimulateCommand(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "Run a maneuver on a simulator, or drive it with recorded inputs");
  cmd->add_option("--vessel", o->vessel, "Simulator: " + VesselChoices())->required();
  cmd->add_option("--maneuver", o->maneuver, ManeuverGrammar() + " (docs/data.md#maneuvers)");
  cmd->add_option("--inputs", o->inputs,
                  "Drive open-loop with the input columns of this CSV (zero-order hold); output "
                  "at its time stamps, initial state from its first row");
  cmd->add_option("--effect", o->effects,
                  "NAME=VALUE, repeatable: input_delay, current (SPEED[:DIR_DEG]), actuator_lag, "
                  "input_bias, sensor_bias, inertia, damping, saturation, surge_force (m/s^2), "
                  "resistance, wind (scale); NAME=VALUE@INPUT for input_delay, actuator_lag, "
                  "input_bias or saturation on one input; missing_term=COEFFICIENT:STATE:TERM");
  cmd->add_option("--wind", o->wind,
                  "A gusty true wind SPEED[:FROM_DEG] (m/s; where it blows from, clockwise from "
                  "north; default a direction from the seed): the record's wind_speed and "
                  "wind_direction are the relative wind aboard (vessel files with a wind "
                  "section)");
  cmd->add_option("--noise", o->noise,
                  "Gaussian noise on every measured channel, as a fraction of its standard "
                  "deviation (0.01 = 1 %)");
  cmd->add_option("--seed", o->seed,
                  "Seed of noise, random maneuvers, and the current's and wind's direction and "
                  "gusts");
  cmd->add_option("--rates", o->rates,
                  "Multi-rate sensors, e.g. imu=50,gps=5,jet=10 (groups or channel names, Hz); "
                  "other rows are written as empty cells")
      ->delimiter(',');
  cmd->add_option("--gusts", o->gusts,
                  "An unmeasured gusty wind on a vessel that logs none (odin3dof, odin-hs): mean "
                  "speed [m/s], where from [deg] (default: drawn from the seed)")
      ->type_name("SPEED[:FROM_DEG]");
  cmd->add_option("--waves", o->waves,
                  "First-order wave motion on the logged motion: significant height [m], peak "
                  "period [s] (default 5 sqrt(Hs)), where from [deg] (default: drawn from the "
                  "seed)")
      ->type_name("HS[:TP[:FROM_DEG]]");
  cmd->add_option("--dropouts", o->dropouts,
                  "Sensor dropouts: NAME=FRACTION of the time lost in gaps of 2 s mean, e.g. "
                  "gps=0.05 (groups imu, gps, jet, or a channel)")
      ->delimiter(',');
  cmd->add_option("--logged", o->logged,
                  "Disturbances the record logs for the methods to read: wind (wind_speed, "
                  "wind_direction aboard, from --gusts), current (current_u, current_v in body "
                  "axes, from --effect current)")
      ->delimiter(',');
  cmd->add_option("--params", o->params,
                  "JSON of parameter overrides (name: value), or a truth/model file's "
                  "\"parameters\" (and its \"effects\": a diagnose model.json simulates as "
                  "extended)");
  cmd->add_option("--duration", o->duration, "Maneuver length [s] (0: the maneuver's default)");
  cmd->add_option("--cruise", o->cruise,
                  "Thrust command of the approach and cruise (default: the vessel's, e.g. "
                  "kvlcc2 rev 91.7)");
  cmd->add_option("--dt", o->dt, "Largest integration step [s]");
  cmd->add_option("--rate", o->rate_hz, "Output and control rate [Hz] (maneuvers)");
  cmd->add_option("--integrator", o->integrator, "rk4 (fixed step) or dopri (adaptive 5(4))")
      ->check(CLI::IsMember({"rk4", "dopri"}));
  cmd->add_option("--out", o->out, "Data CSV to write (and F.truth.json beside it)")->required();
  cmd->callback([o] { RunSimulate(*o); });
}

}  // namespace usvid
