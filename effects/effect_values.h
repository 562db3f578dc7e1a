// The catalogue's effects as numbers of scalar type T, so that their sizes can be fitted
// through a differentiable rollout. Neutral values (no effect) are the defaults. The delay is a
// double: it moves the input signal in time and is found by a bounded search, not by
// derivatives.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/expression.h"
#include "effects/effect.h"

namespace usvid {

// A missing term resolved against a vessel: which state's derivative gains it, and where its
// variables are in the plant's states and inputs.
struct ResolvedTerm {
  int state = 0;                 // index into the vessel's states
  Expression term;               // in the vessel's channel names
  std::vector<int> slots;        // per term variable: a state index, or kStates + an input index
  std::string state_name, text;  // as the effect names them (a term given twice replaces)
};

// d(state)/dt += coefficient * term(x, u); the resolved part is shared by every scalar type.
template <typename T>
struct ExtraTerm {
  std::shared_ptr<const ResolvedTerm> resolved;
  T coefficient = T(0);
};

// `effect` (a missing_term) resolved against the vessel's state and input names; InputError
// naming a channel that is neither.
std::shared_ptr<const ResolvedTerm> ResolveTerm(const Effect& effect,
                                                const std::vector<std::string>& state_names,
                                                const std::vector<std::string>& input_names);

template <typename T>
struct EffectValues {
  double delay_s = 0.0;
  T current_north = T(0);
  T current_east = T(0);
  T lag_time_constant_s = T(0);  // 0: applied input = commanded input
  T input_bias = T(0);           // added to the vessel's yaw input
  T sensor_bias = T(0);          // added to the measured rate channel
  T inertia_scale = T(1);
  T damping_scale = T(1);
  T resistance_scale = T(1);         // surge resistance parameters (ParamGroup::kResistance)
  double saturation_fraction = 0.0;  // 0: no clipping
  T surge_acceleration = T(0);       // added to the surge (or speed) state's derivative
  T wind_scale = T(0);  // the measured wind's force, times the vessel's wind model, added
  // An unmeasured disturbance (wind gusts, simulation/wind_gusts.h) as accelerations of the
  // sway state v and the yaw rate r; with surge_acceleration, the simulation sets them anew at
  // every control period. Not an effect of the catalogue: 0 in every fit.
  T sway_acceleration = T(0);
  T yaw_acceleration = T(0);
  // Extra delay per input, on top of delay_s (empty: none; shorter than the inputs: none for
  // the rest): input_delay on some inputs only.
  std::vector<double> input_delays_s;
  // Which inputs (bit i: input i) the actuator lag and the saturation act on: all by default.
  uint32_t lag_inputs = ~0u;
  uint32_t saturation_inputs = ~0u;
  int bias_input = -1;  // the input input_bias is added to; -1: the vessel's yaw input
  std::vector<ExtraTerm<T>> extra_terms;  // missing_term effects
  // The measured wind inputs hold the air's velocity over the ground [north, east] instead of
  // the relative wind aboard: the plant makes the relative wind from its own heading and
  // velocities (a free run of a log, simulation/recorded_inputs.h). Not an effect.
  bool wind_over_ground = false;
};

// The values of a list of effects (each kind at most once per set of inputs). `input_names`
// and `state_names` are the vessel's, which an effect's `inputs` and a missing term name; a
// name not among them is an InputError naming both.
EffectValues<double> ValuesOf(const std::vector<Effect>& effects,
                              const std::vector<std::string>& input_names = {},
                              const std::vector<std::string>& state_names = {});
// `effect` set in `values` (replacing that kind's value; on some inputs, those inputs' values;
// a missing term, the same state and term).
void SetEffect(const Effect& effect, EffectValues<double>& values,
               const std::vector<std::string>& input_names = {},
               const std::vector<std::string>& state_names = {});
// The bit mask of `inputs` among `input_names` (all bits when `inputs` is empty).
uint32_t InputMask(const Effect& effect, const std::vector<std::string>& input_names);

// Values of scalar type T (constants: no derivative parts).
template <typename T>
EffectValues<T> CastValues(const EffectValues<double>& e) {
  EffectValues<T> out;
  out.delay_s = e.delay_s;
  out.current_north = T(e.current_north);
  out.current_east = T(e.current_east);
  out.lag_time_constant_s = T(e.lag_time_constant_s);
  out.input_bias = T(e.input_bias);
  out.sensor_bias = T(e.sensor_bias);
  out.inertia_scale = T(e.inertia_scale);
  out.damping_scale = T(e.damping_scale);
  out.resistance_scale = T(e.resistance_scale);
  out.saturation_fraction = e.saturation_fraction;
  out.surge_acceleration = T(e.surge_acceleration);
  out.wind_scale = T(e.wind_scale);
  out.sway_acceleration = T(e.sway_acceleration);
  out.yaw_acceleration = T(e.yaw_acceleration);
  out.input_delays_s = e.input_delays_s;
  out.lag_inputs = e.lag_inputs;
  out.saturation_inputs = e.saturation_inputs;
  out.bias_input = e.bias_input;
  out.wind_over_ground = e.wind_over_ground;
  for (const ExtraTerm<double>& t : e.extra_terms)
    out.extra_terms.push_back({t.resolved, T(t.coefficient)});
  return out;
}

// +-limit per input for `saturation`: fraction x the peak |command| of each input channel that
// saturates (bit i of `inputs`; infinite when there is no saturation, the input does not
// saturate or the channel never moves).
template <int N>
std::array<double, N> SaturationLimits(double fraction, const std::array<double, N>& peak,
                                       uint32_t inputs = ~0u) {
  std::array<double, N> limit;
  for (int i = 0; i < N; ++i)
    limit[i] = fraction > 0.0 && peak[i] > 0.0 && ((inputs >> i) & 1u)
                   ? fraction * peak[i]
                   : std::numeric_limits<double>::infinity();
  return limit;
}

}  // namespace usvid
