// Any vessel V wrapped with the catalogue's effects: one implementation, used by simulation and
// by diagnosis. The plant state is V's state followed by one applied-input state per input
// (the actuator lag's memory). With commanded input u_c (already delayed by the caller):
//   u_s = clamp(u_c, -limit, +limit)                        (saturation)
//   u_a = x_lag,  x_lag' = (u_s - x_lag) / time_constant     (actuator_lag; else u_a = u_s)
//   u_a[yaw] += input_bias                                   (input_bias)
// each on the inputs it acts on (EffectValues: lag_inputs, saturation_inputs, bias_input),
// never on a measured disturbance (a wind input, CommandedInputs in simulators/vessel.h).
//   x' = V::Derivative(x, u_a, p_eff, {current, wind})       (current, wind)
// where p_eff is p with inertia, damping and resistance parameters scaled (inertia, damping,
// resistance). The measured
// rate channel carries sensor_bias (MeasuredRate); input_delay shifts u_c in time (caller);
// surge_force adds its acceleration to the surge state's derivative (u, else U, else the msd's v),
// and each missing term coefficient * term(x, u_a) to its state's derivative. An unmeasured
// disturbance (gusts) adds its accelerations to the surge, sway (v) and yaw rate (r) states.
// A measured wind given over the ground (EffectValues::wind_over_ground) becomes the relative
// wind of the plant's own heading and velocities before V sees it (maneuvers/true_wind.h).
#pragma once

#include <array>
#include <initializer_list>
#include <string_view>

#include "effects/effect_values.h"
#include "simulators/scalar.h"
#include "simulators/vessel.h"

namespace usvid {

// The index of input `name` among V's inputs; -1: none.
template <Vessel V>
constexpr int FindInput(std::string_view name) {
  if constexpr (requires { V::kInputNames; }) {
    for (int i = 0; i < V::kInputs; ++i)
      if (V::kInputNames[i] == name) return i;
  }
  return -1;
}

// The index of the first of `names` among V's states; -1: none of them.
template <Vessel V>
constexpr int FindState(std::initializer_list<std::string_view> names) {
  for (std::string_view name : names)
    for (int i = 0; i < V::kStates; ++i)
      if (V::kStateNames[i] == name) return i;
  return -1;
}

template <Vessel V>
struct Plant {
  static constexpr int kStates = V::kStates + V::kInputs;
  static constexpr int kCommanded = CommandedInputs<V>();
  // The state a surge force accelerates: u, else U, else v (the msd's velocity); -1: none.
  static constexpr int kSurgeState = FindState<V>({"u", "U", "v"});
  // The states a disturbance's sway and yaw accelerations act on: v beside a surge u, and r.
  static constexpr int kSwayState = FindState<V>({"u"}) >= 0 ? FindState<V>({"v"}) : -1;
  static constexpr int kYawRateState = FindState<V>({"r"});
  // A wind over the ground needs the measured wind pair, a heading and surge-sway states.
  static constexpr int kWindSpeedInput = FindInput<V>("wind_speed");
  static constexpr int kWindDirectionInput = FindInput<V>("wind_direction");
  static constexpr int kHeadingState = FindState<V>({"psi"});
  static constexpr bool kWindOverGround =
      kWindSpeedInput >= 0 && kWindDirectionInput >= 0 && kHeadingState >= 0 && kSwayState >= 0;

  template <typename T>
  static void ScaleParams(const T* p, const EffectValues<T>& e, T* p_eff) {
    for (int i = 0; i < V::kParams; ++i) {
      switch (V::kParamGroups[i]) {
        case ParamGroup::kInertia:
          p_eff[i] = p[i] * e.inertia_scale;
          break;
        case ParamGroup::kDamping:
          p_eff[i] = p[i] * e.damping_scale;
          break;
        case ParamGroup::kResistance:
          p_eff[i] = p[i] * e.damping_scale * e.resistance_scale;
          break;
        case ParamGroup::kOther:
          p_eff[i] = p[i];
          break;
      }
    }
  }

  // x: plant state; u_cmd: commanded (delayed) input; p_eff: from ScaleParams.
  template <typename T>
  static void Derivative(const T* x, const T* u_cmd, const T* p_eff, const EffectValues<T>& e,
                         const std::array<double, V::kInputs>& limit, T* dx) {
    std::array<T, V::kInputs> u_sat;
    for (int i = 0; i < V::kInputs; ++i) {
      u_sat[i] = u_cmd[i];
      if (i >= kCommanded) continue;  // a measured wind is not an actuator
      if (ValueOf(u_sat[i]) > limit[i]) u_sat[i] = T(limit[i]);
      if (ValueOf(u_sat[i]) < -limit[i]) u_sat[i] = T(-limit[i]);
    }
    const T* lag = x + V::kStates;
    T* dlag = dx + V::kStates;
    std::array<T, V::kInputs> u_applied;
    const bool lagged = ValueOf(e.lag_time_constant_s) > 0.0;
    for (int i = 0; i < V::kInputs; ++i) {
      if (lagged && i < kCommanded && ((e.lag_inputs >> i) & 1u)) {
        u_applied[i] = lag[i];
        dlag[i] = (u_sat[i] - lag[i]) / e.lag_time_constant_s;
      } else {
        u_applied[i] = u_sat[i];
        dlag[i] = T(0);
      }
    }
    u_applied[e.bias_input >= 0 && e.bias_input < V::kInputs ? e.bias_input : V::kYawInput] +=
        e.input_bias;
    if constexpr (kWindOverGround)
      if (e.wind_over_ground) RelativeWindAboard(x, u_applied);
    const Environment<T> env{e.current_north, e.current_east, e.wind_scale};
    V::template Derivative<T>(x, u_applied.data(), p_eff, env, dx);
    if constexpr (kSurgeState >= 0) dx[kSurgeState] += e.surge_acceleration;
    // Never fitted (no derivative parts), so skipped when zero: a fit's Jets pay nothing.
    if constexpr (kSwayState >= 0)
      if (ValueOf(e.sway_acceleration) != 0.0) dx[kSwayState] += e.sway_acceleration;
    if constexpr (kYawRateState >= 0)
      if (ValueOf(e.yaw_acceleration) != 0.0) dx[kYawRateState] += e.yaw_acceleration;
    for (const ExtraTerm<T>& extra : e.extra_terms) {
      const ResolvedTerm& t = *extra.resolved;
      std::array<T, V::kStates + V::kInputs> values;
      for (size_t i = 0; i < t.slots.size(); ++i)
        values[i] = t.slots[i] < V::kStates ? x[t.slots[i]] : u_applied[t.slots[i] - V::kStates];
      dx[t.state] += extra.coefficient * t.term.template EvaluateT<T>(values.data());
    }
  }

  // The air's velocity over the ground [north, east] in the wind inputs turned into the wind
  // aboard: its speed, and where it blows from, clockwise from the bow (RelativeWindOf in
  // maneuvers/true_wind.h, in scalar T).
  template <typename T>
  static void RelativeWindAboard(const T* x, std::array<T, V::kInputs>& u) {
    using std::atan2;
    using std::cos;
    using std::sin;
    using std::sqrt;
    const T c = cos(x[kHeadingState]), s = sin(x[kHeadingState]);
    const T air_n = u[kWindSpeedInput], air_e = u[kWindDirectionInput];
    const T a_u = c * air_n + s * air_e - x[kSurgeState];
    const T a_v = -s * air_n + c * air_e - x[kSwayState];
    if (ValueOf(a_u) == 0.0 && ValueOf(a_v) == 0.0) {  // calm aboard: no derivative to take
      u[kWindSpeedInput] = T(0);
      u[kWindDirectionInput] = T(0);
      return;
    }
    u[kWindSpeedInput] = sqrt(a_u * a_u + a_v * a_v);
    u[kWindDirectionInput] = atan2(-a_v, -a_u);
  }

  // The state a plant starts in: the vessel state, and the lag memory at the first command.
  template <typename T>
  static void InitialLagState(const T* u_cmd, T* x) {
    for (int i = 0; i < V::kInputs; ++i) x[V::kStates + i] = u_cmd[i];
  }
};

}  // namespace usvid
