// Mass-spring-damper, vessel `msd` (docs/model.md#msd):
//   m x'' + d x' + k x = f,   m = 10 kg, d = 1 N s/m, k = 2 N/m,
// so x'' = -0.2 x - 0.1 x' + 0.1 f. States x [m], v [m/s]; input f [N].
// A current (effect `current`) is a medium moving along x at current_north: the damper acts on
// the relative velocity v - current_north.
#pragma once

#include "simulators/vessel.h"

namespace usvid {

struct Msd {
  static constexpr std::string_view kName = "msd";
  static constexpr int kStates = 2, kInputs = 1, kParams = 3;
  static constexpr std::array<std::string_view, kStates> kStateNames = {"x", "v"};
  static constexpr std::array<std::string_view, kInputs> kInputNames = {"f"};
  static constexpr std::array<std::string_view, kParams> kParamNames = {"m", "d", "k"};
  static constexpr std::array<double, kParams> kDefaultParams = {10.0, 1.0, 2.0};
  static constexpr std::array<ParamGroup, kParams> kParamGroups = {
      ParamGroup::kInertia, ParamGroup::kDamping, ParamGroup::kOther};
  static constexpr std::array<double, kInputs> kInputMin = {-100.0};
  static constexpr std::array<double, kInputs> kInputMax = {100.0};
  static constexpr int kYawInput = 0, kThrustInput = -1, kRateState = 1, kHeadingState = -1;

  enum Param { kMass, kDamping, kStiffness };  // indices, in kParamNames order

  template <typename T>
  static void Derivative(const T* x, const T* u, const T* p, const Environment<T>& env, T* dx) {
    dx[0] = x[1];
    dx[1] = (u[0] - p[kDamping] * (x[1] - env.current_north) - p[kStiffness] * x[0]) / p[kMass];
  }
};

}  // namespace usvid
