// The catalogue of what a simulation can get wrong (docs/data.md#effects), shared by
// `usvid simulate --effect NAME=VALUE` and `usvid diagnose`:
//   input_delay   every input reaches the plant late by delay_s [s]
//   current       constant irrotational current current_north, current_east [m/s]; damping
//                 acts on the velocity relative to the water
//   actuator_lag  first-order lag, time_constant_s [s], between commanded and applied input
//   input_bias    constant offset `bias` [input units] added to the yaw input
//   sensor_bias   constant offset `bias` [rad/s] on the measured yaw rate r
//   inertia       mass and inertia parameters times `scale`
//   damping       damping parameters times `scale`
//   saturation    each input clipped at +-fraction x its peak absolute command
//   surge_force   a constant surge force the model lacks, as an acceleration [m/s^2] on the
//                 surge (or speed) state: a propulsion mismatch, a towing force
//   resistance    the surge resistance parameters times `scale` (the rest of the damping not)
//   wind          the measured relative wind (inputs wind_speed, wind_direction) pushes the
//                 vessel with `scale` times its wind model's force, on top of what the model
//                 has: a model that ignores the wind (a vessel file with wind model none) lacks
//                 scale 1 of it. Only vessels with a wind model (simulators/wind_force.h).
// input_delay, actuator_lag, input_bias and saturation may act on some inputs only
// (Effect::inputs, by channel name; `--effect input_delay=1.0@tau_n`): a delay or lag on one
// actuator, a bias on another input than the yaw input, one actuator that saturates.
// Beyond the catalogue, missing_term: a term `coefficient * TERM` (an expression in the
// vessel's state and input names, docs/diagnose.md) missing from one state's derivative; the
// diagnosis proposes and fits it, `--effect missing_term=COEFFICIENT:STATE:TERM` hides one.
// ParseEffect throws InputError naming the --effect item and the rule it breaks.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace usvid {

enum class EffectKind {
  kInputDelay,
  kCurrent,
  kActuatorLag,
  kInputBias,
  kSensorBias,
  kInertia,
  kDamping,
  kSaturation,
  kSurgeForce,
  kResistance,
  kWind,
  kMissingTerm  // not in the catalogue: proposed by the diagnosis's residual search
};

struct EffectInfo {
  EffectKind kind;
  std::string_view name;
  std::string_view main_parameter;  // what NAME=VALUE sets
  std::string_view meaning;
};

// The catalogue: what the diagnosis fits blindly (missing_term is not among them).
const std::array<EffectInfo, 11>& EffectCatalogue();
const EffectInfo& InfoOf(EffectKind kind);

struct Effect {
  EffectKind kind;
  std::map<std::string, double> parameters;  // names of docs/data.md#effects
  // The input channels it acts on; empty: the kind's default (every input; the yaw input for
  // input_bias). Only for the kinds that OnInputs allows.
  std::vector<std::string> inputs = {};
  // missing_term: the state whose derivative gains coefficient * term, and the term.
  std::string state = {}, term = {};

  std::string_view name() const { return InfoOf(kind).name; }
  double at(const std::string& parameter) const { return parameters.at(parameter); }
};

// Whether an effect of this kind can act on some inputs only.
bool OnInputs(EffectKind kind);
// The name, with the inputs of an effect on some inputs only ("input_delay@tau_n") or the
// state and term of a missing term ("missing_term r: abs(v)*v").
std::string EffectLabel(const Effect& effect);

// The same effect in a list: the kind, and the inputs or the state and term it acts on.
bool SameEffect(const Effect& a, const Effect& b);

// "NAME=VALUE" with the main parameter; `current=SPEED` takes a direction drawn from `seed`
// (uniform over the compass), `current=SPEED:DIRECTION_DEG` the direction the water flows to,
// clockwise from north; "NAME=VALUE@IN1+IN2" the input channels it acts on (OnInputs kinds).
Effect ParseEffect(const std::string& spec, uint64_t seed);
std::vector<Effect> ParseEffects(const std::vector<std::string>& specs, uint64_t seed);

nlohmann::json EffectToJson(const Effect& effect);
Effect EffectFromJson(const nlohmann::json& value);

// The "effects" of a model or truth file (a diagnose model.json, a simulate F.truth.json); none
// when it has no such field. Errors name the file.
std::vector<Effect> EffectsOfFile(const std::string& path);
// `base` with each of `overrides` put in place of the same kind (or added).
std::vector<Effect> MergeEffects(std::vector<Effect> base, const std::vector<Effect>& overrides);

}  // namespace usvid
