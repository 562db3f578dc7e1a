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
#include "effects/effect_values.h"
#include "maneuvers/maneuver_factory.h"
#include "maneuvers/true_wind.h"
#include "sensors/sample_rates.h"
#include "sensors/sensor_chain.h"
#include "simulation/logged_disturbances.h"
#include "simulation/vessel_simulator.h"
#include "simulation/wind_gusts.h"

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

// The vessel's actuation, its cruise thrust set by --cruise when given.
Actuation CruiseActuation(const SimulateOptions& o, const VesselInfo& info) {
  Actuation act = info.actuation;
  if (!o.cruise) return act;
  if (act.thrust_input < 0)
    throw InputError("--cruise: vessel " + info.name + " has no thrust input");
  if (!(*o.cruise >= act.input_min[act.thrust_input] &&
        *o.cruise <= act.input_max[act.thrust_input]))
    throw InputError("--cruise: " + std::to_string(*o.cruise) + " is outside the range of " +
                     act.input_names[act.thrust_input]);
  act.thrust_cruise = *o.cruise;
  return act;
}

// --maneuver run on the vessel, under --wind and --gusts (those written to `truth`).
SimulationResult SimulateManeuver(const SimulateOptions& o, const VesselSimulator& sim,
                                  const std::vector<double>& params,
                                  const EffectValues<double>& values, RunOptions& run,
                                  std::optional<WindGusts>& gusts, nlohmann::json& truth) {
  const VesselInfo& info = sim.Info();
  // Multi-rate sensors need an output grid at least as fast as the fastest sensor.
  for (const auto& [_, hz] : ParseRateItems(o.rates)) run.rate_hz = std::max(run.rate_hz, hz);
  const Actuation act = CruiseActuation(o, info);
  auto maneuver = MakeManeuver(o.maneuver, act, o.duration, o.seed);
  if (!o.wind.empty())
    maneuver = UnderTrueWind(std::move(maneuver), act, ParseWind(o.wind, o.seed), o.seed);
  if (!o.gusts.empty()) {
    gusts = MakeWindGusts(info, o.gusts, o.seed, "--gusts '" + o.gusts + "'");
    run.disturbance = GustDisturbance(*gusts, o.seed);
    truth["gusts"] = WindGustsToJson(*gusts);
    truth["gusts"]["measured"] = std::ranges::find(o.logged, "wind") != o.logged.end();
  }
  std::cerr << "usvid simulate: " << info.name << ", " << maneuver->Spec() << ", up to "
            << maneuver->Duration() << " s at " << run.rate_hz << " Hz\n";
  return sim.RunManeuver(*maneuver, params, values, run);
}

// The run's truth beside what the sensors logged: the parameters, effects, noise and grid.
void AddRunTruth(const SimulateOptions& o, const VesselInfo& info,
                 const std::vector<double>& params, const std::vector<Effect>& effects,
                 const std::vector<std::string>& measured, const SensorLog& logged,
                 const RunOptions& run, const SimulationResult& result, nlohmann::json& truth) {
  nlohmann::json p = nlohmann::json::object();
  for (size_t i = 0; i < params.size(); ++i) p[info.params[i]] = params[i];
  nlohmann::json e = nlohmann::json::array();
  for (const Effect& effect : effects) e.push_back(EffectToJson(effect));
  nlohmann::json noise_sd = nlohmann::json::object();
  for (size_t i = 0; i < measured.size(); ++i) noise_sd[measured[i]] = logged.noise_sd[i];
  truth.update({{"vessel", info.name},
                {"parameters", p},
                {"effects", e},
                {"seed", o.seed},
                {"noise", {{"level", o.noise}, {"sd", noise_sd}}},
                {"states", info.states},
                {"derived", info.derived},
                {"inputs", info.inputs},
                {"dt", run.dt},
                {"rate_hz", run.rate_hz},
                {"integrator", o.integrator},
                {"transport_delay_s", info.transport_delay_s},
                {"sensor_rates_hz", logged.rates},
                {"duration_s", result.data.duration()},
                {"run_in_s", result.run_in_s}});
  if (!result.maneuver.is_null()) truth["maneuver"] = result.maneuver;
  if (o.cruise) truth["cruise"] = *o.cruise;
}

void RunSimulate(const SimulateOptions& o) {
  if (o.maneuver.empty() == o.inputs.empty())
    throw InputError("simulate: give exactly one of --maneuver and --inputs");
  if (!(o.dt > 0) || !(o.rate_hz > 0)) throw InputError("--dt and --rate: must be positive");
  CheckOutputFile(o.out);
  const VesselSimulator& sim = FindVessel(o.vessel);
  const VesselInfo& info = sim.Info();
  const std::vector<Effect> effects = SimulatedEffects(o, info);
  const EffectValues<double> values = ValuesOf(effects, info.inputs, info.states);
  CheckLoggedDisturbances(o.logged, !o.gusts.empty(), effects, "--logged");
  std::vector<double> params = info.default_params;
  if (!o.params.empty()) params = info.ParamsFromFile(o.params);
  RunOptions run;
  run.dt = o.dt;
  run.rate_hz = o.rate_hz;
  run.integrator = o.integrator == "dopri" ? Integrator::kDormandPrince : Integrator::kRk4;

  SimulationResult result;
  nlohmann::json truth;
  std::optional<WindGusts> gusts;
  if (!o.maneuver.empty()) {
    result = SimulateManeuver(o, sim, params, values, run, gusts, truth);
  } else {
    if (!o.wind.empty() || !o.gusts.empty())
      throw InputError(
          "simulate: --wind and --gusts make a maneuver's wind; with --inputs the file's "
          "wind_speed and wind_direction columns are the wind");
    const Dataset in = ReadDataFile(o.inputs, "usvid simulate");
    result = sim.RunInputs(in, params, values, run);
    truth["inputs_file"] = o.inputs;
  }
  if (result.diverged)
    throw InputError("simulate: the " + info.name + " simulation diverged at t = " +
                     std::to_string(result.diverged_at_s) + " s (check --params and inputs)");

  // What the sensors log: the waves' motion on top, noise, each sensor's rate, its gaps.
  Dataset& data = result.data;
  std::vector<std::string> measured = info.states;
  measured.insert(measured.end(), info.derived.begin(), info.derived.end());
  for (std::string& c : LogDisturbances(data, o.logged, gusts ? &*gusts : nullptr, o.seed, values))
    measured.push_back(std::move(c));
  if (!o.logged.empty()) truth["logged"] = o.logged;
  const SensorLog logged = LogAsSensors(data, measured, {o.waves, o.noise, o.rates, o.dropouts},
                                        WaveHullLength(info.length_m), o.seed);
  if (logged.sea) truth["waves"] = WaveSeaToJson(*logged.sea, logged.hull_length_m);
  if (!logged.dropouts.empty()) truth["dropouts"] = DropoutsToJson(logged.dropouts);
  AddRunTruth(o, info, params, effects, measured, logged, run, result, truth);

  WriteDatasetCsv(o.out, data);
  WriteJsonFile(TruthPath(o.out), truth);
  std::cerr << "usvid simulate: wrote " << o.out << " (" << data.rows() << " rows, "
            << data.duration() << " s) and " << TruthPath(o.out) << '\n';
}

}  // namespace

void AddSimulateCommand(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "Run a maneuver on a simulator, or drive it with recorded inputs");
  cmd->add_option("--vessel", o->vessel, "Simulator: " + VesselChoices())->required();
  cmd->add_option("--maneuver", o->maneuver,
                  "zigzag[:A/B], turning[:A], stepgrid[:T/Y], random-steps[:HOLD_S], "
                  "prbs[:CLOCK_S], multisine[:FMAX_HZ], autopilot[:HOLD_S]");
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
