// The dynamics interface every simulator follows, written once for every scalar type T
// (double, ceres::Jet) so that a whole rollout can be differentiated.
//
// A vessel is a struct with compile-time sizes and names and one templated function:
//   static constexpr std::string_view kName;
//   static constexpr int kStates, kInputs, kParams;
//   static constexpr std::array<std::string_view, kStates> kStateNames;   (and kInputNames,
//   kParamNames, kDefaultParams, kParamGroups, kInputMin, kInputMax)
//   static constexpr int kYawInput;    // the input that turns it (tau_n, nozzle, delta; msd: f)
//   static constexpr int kThrustInput; // the input that drives it forward (-1: none)
//   static constexpr int kRateState;   // the rate gyro's channel (r; msd: v)
//   static constexpr int kHeadingState;// psi or chi (-1: none)
// and optionally
//   static constexpr int kCommandedInputs; // inputs from this index on are measured
//                                          // disturbances (wind), not commands
//   template <typename T>
//   static void Derivative(const T* x, const T* u, const T* p, const Environment<T>& env,
//                          T* dx);
// Derivative must not allocate and must use unqualified math (`using std::abs;`) so the Jet
// overloads are found. Units are SI with angles in radians; NED, body velocities nu = [u v r].
#pragma once

#include <array>
#include <concepts>
#include <string_view>

namespace usvid {

// What a parameter stands for, so that effects can scale a whole class of them
// (effects `inertia`, `damping` and `resistance` of docs/data.md#effects). kResistance is the
// part of the damping that resists forward motion (surge resistance): `damping` scales it with
// the rest, `resistance` alone.
enum class ParamGroup { kInertia, kDamping, kResistance, kOther };

// The world around the hull: a constant irrotational current, earth-fixed [m/s], and a wind
// force the model lacks: `wind_scale` times the vessel's own wind model, driven by its measured
// wind inputs, added to what the model has (effect `wind`; vessels without a wind model ignore
// it).
template <typename T>
struct Environment {
  T current_north = T(0);
  T current_east = T(0);
  T wind_scale = T(0);
};

// The inputs that are commands (rudder, propeller, forces): all but the measured disturbances
// that follow them (kCommandedInputs). Maneuvers, actuator effects and the equation methods'
// default inputs take these alone.
template <typename V>
constexpr int CommandedInputs() {
  if constexpr (requires { V::kCommandedInputs; })
    return V::kCommandedInputs;
  else
    return V::kInputs;
}

// Positions and heading: they follow from the velocities by the kinematics, so fits and scores
// of the dynamics leave them out.
constexpr bool IsPositionOrHeading(std::string_view state) {
  return state == "north" || state == "east" || state == "psi" || state == "chi";
}

template <typename V>
concept Vessel = requires {
  { V::kName } -> std::convertible_to<std::string_view>;
  requires V::kStates >
  0 && V::kInputs > 0 && V::kParams > 0;
  requires V::kStateNames.size() == V::kStates;
  requires V::kInputNames.size() == V::kInputs;
  requires V::kParamNames.size() == V::kParams;
  requires V::kDefaultParams.size() == V::kParams;
  requires V::kParamGroups.size() == V::kParams;
  requires V::kInputMin.size() == V::kInputs&& V::kInputMax.size() == V::kInputs;
  { V::kYawInput } -> std::convertible_to<int>;
  { V::kThrustInput } -> std::convertible_to<int>;
  { V::kRateState } -> std::convertible_to<int>;
  { V::kHeadingState } -> std::convertible_to<int>;
  requires requires(const double* x, const double* u, const double* p, double* dx,
                    const Environment<double>& env) {
    V::template Derivative<double>(x, u, p, env, dx);
  };
};

}  // namespace usvid
