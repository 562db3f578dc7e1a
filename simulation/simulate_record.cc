#include "simulation/simulate_record.h"

#include <algorithm>

#include "core/error.h"
#include "core/parse_number.h"
#include "effects/effect_values.h"
#include "maneuvers/maneuver_factory.h"
#include "sensors/sample_rates.h"
#include "sensors/wave_motion.h"
#include "simulation/logged_disturbances.h"
#include "simulation/vessel_simulator.h"
#include "simulation/wind_gusts.h"

namespace usvid {
namespace {

// The vessel's actuation, its cruise thrust set by the recipe when given.
Actuation CruiseActuation(const RecordRecipe& r, const VesselInfo& info) {
  Actuation act = info.actuation;
  if (!r.cruise) return act;
  if (act.thrust_input < 0)
    throw InputError("--cruise: vessel " + info.name + " has no thrust input");
  if (!(*r.cruise >= act.input_min[act.thrust_input] &&
        *r.cruise <= act.input_max[act.thrust_input]))
    throw InputError("--cruise: " + std::to_string(*r.cruise) + " is outside the range of " +
                     act.input_names[act.thrust_input]);
  act.thrust_cruise = *r.cruise;
  return act;
}

// The run's truth beside what the sensors logged: the parameters, effects, noise and grid.
nlohmann::json RunTruth(const RecordRecipe& r, const VesselInfo& info,
                        const std::vector<double>& params, const std::vector<std::string>& measured,
                        const SensorLog& logged, const RunOptions& run,
                        const SimulationResult& result) {
  nlohmann::json p = nlohmann::json::object();
  for (size_t i = 0; i < params.size(); ++i) p[info.params[i]] = params[i];
  nlohmann::json e = nlohmann::json::array();
  for (const Effect& effect : r.effects) e.push_back(EffectToJson(effect));
  nlohmann::json noise_sd = nlohmann::json::object();
  for (size_t i = 0; i < measured.size(); ++i) noise_sd[measured[i]] = logged.noise_sd[i];
  nlohmann::json truth = {
      {"vessel", info.name},
      {"parameters", p},
      {"effects", e},
      {"seed", r.seed},
      {"noise", {{"level", r.sensors.noise}, {"sd", noise_sd}}},
      {"states", info.states},
      {"derived", info.derived},
      {"inputs", info.inputs},
      {"dt", run.dt},
      {"rate_hz", run.rate_hz},
      {"integrator", run.integrator == Integrator::kDormandPrince ? "dopri" : "rk4"},
      {"transport_delay_s", info.transport_delay_s},
      {"sensor_rates_hz", logged.rates},
      {"duration_s", result.data.duration()},
      {"run_in_s", result.run_in_s}};
  if (!result.maneuver.is_null()) truth["maneuver"] = result.maneuver;
  if (r.cruise) truth["cruise"] = *r.cruise;
  if (!r.logged.empty()) truth["logged"] = r.logged;
  if (logged.sea) truth["waves"] = WaveSeaToJson(*logged.sea, logged.hull_length_m);
  if (!logged.dropouts.empty()) truth["dropouts"] = DropoutsToJson(logged.dropouts);
  return truth;
}

}  // namespace

SimulatedRecord SimulateRecord(const RecordRecipe& r,
                               const std::function<void(const std::string&)>& log) {
  const VesselSimulator& sim = r.vessel.Simulator();
  const VesselInfo& info = sim.Info();
  const std::vector<double>& params = r.params.empty() ? info.default_params : r.params;
  const EffectValues<double> values = ValuesOf(r.effects, info.inputs, info.states);
  RunOptions run = r.run;
  // Multi-rate sensors need an output grid at least as fast as the fastest sensor.
  for (const auto& [_, hz] : ParseRateItems(r.sensors.rates))
    run.rate_hz = std::max(run.rate_hz, hz);
  std::optional<WindGusts> gusts;
  nlohmann::json gusts_truth;
  SimulationResult result;
  if (!r.maneuver.empty()) {
    const Actuation act = CruiseActuation(r, info);
    auto maneuver = MakeManeuver(r.maneuver, act, r.duration_s, r.seed);
    if (r.wind) maneuver = UnderTrueWind(std::move(maneuver), act, *r.wind, r.seed);
    if (!r.gusts.empty()) {
      gusts = MakeWindGusts(info, r.gusts, r.seed, r.gusts_where);
      run.disturbance = GustDisturbance(*gusts, r.seed);
      gusts_truth = WindGustsToJson(*gusts);
      gusts_truth["measured"] = std::ranges::find(r.logged, "wind") != r.logged.end();
    }
    if (log)
      log(info.name + ", " + maneuver->Spec() + ", up to " + FormatNumber(maneuver->Duration()) +
          " s at " + FormatNumber(run.rate_hz) + " Hz");
    result = sim.RunManeuver(*maneuver, params, values, run);
  } else {
    if (r.inputs == nullptr) throw InputError("simulate: give a maneuver or recorded inputs");
    result = sim.RunInputs(*r.inputs, params, values, run);
  }
  // What the sensors log: the logged disturbances from the true motion, then the waves' motion
  // on top, noise, each sensor's rate, its gaps.
  std::vector<std::string> measured = info.states;
  measured.insert(measured.end(), info.derived.begin(), info.derived.end());
  for (std::string& c :
       LogDisturbances(result.data, r.logged, gusts ? &*gusts : nullptr, r.seed, values))
    measured.push_back(std::move(c));
  const SensorLog logged =
      LogAsSensors(result.data, measured, r.sensors, WaveHullLength(info.length_m), r.seed);
  SimulatedRecord out;
  out.truth = RunTruth(r, info, params, measured, logged, run, result);
  if (!gusts_truth.is_null()) out.truth["gusts"] = std::move(gusts_truth);
  out.diverged = result.diverged;
  out.diverged_at_s = result.diverged_at_s;
  out.data = std::move(result.data);
  return out;
}

}  // namespace usvid
