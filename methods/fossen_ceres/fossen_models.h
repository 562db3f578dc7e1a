// The parametric models `fossen-ceres` fits. Both are odin3dof's Fossen 3-DOF form
// (simulators/odin3dof.h, parameters m11 m22 m33 Xu Xuu Yv Yvv Nv Nr Nrr):
//   M nu' + C(nu) nu + D(nu) nu = tau(in; p),
// and differ only in the input map tau(in; p):
//  - Odin3DofModel: inputs tau_x, tau_y [N], tau_n [N m] are the forces themselves;
//  - WaterjetModel: inputs throttle [0, 1], nozzle [rad], bucket [-1, 1] of a twin-waterjet
//    vessel (odin-hs) through thrust gains Tx, Ty [N], Tn [N m] (13 parameters):
//      T = (0.2 + 0.8 throttle)^2       (thrust ~ rpm^2, rpm / 2000 = 0.2 + 0.8 throttle),
//      tau_x = Tx T bucket,  tau_y = -Ty T nozzle,  tau_n = Tn T nozzle
//    (positive nozzle turns to starboard, r > 0). It has no actuator dynamics. Multiplying all
//    13 parameters by one factor leaves the model unchanged, so fits hold m11 at its start.
// Each model is also a Vessel (states north, east, psi, u, v, r) so that the multiple-shooting
// fit simulates it with the templated plant; kStart are the fits' starting values.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "core/parse_number.h"
#include "simulators/odin3dof.h"

namespace usvid::fossen {

// Members shared by both models: the states, the vessel-concept constants, the dynamics.
template <typename Model>
struct FossenModelBase {
  static constexpr int kStates = 6, kInputs = 3;
  static constexpr std::array<std::string_view, kStates> kStateNames = Odin3Dof::kStateNames;
  static constexpr int kThrustInput = 0, kRateState = 5, kHeadingState = 2;

  // Odin3Dof's dynamics driven by tau(in; p); p starts with odin3dof's 10 parameters.
  template <typename T>
  static void Derivative(const T* x, const T* in, const T* p, const Environment<T>& env, T* dx) {
    T tau[3];
    Model::Forces(p, in, tau);
    Odin3Dof::Derivative<T>(x, tau, p, env, dx);
  }
};

struct Odin3DofModel : FossenModelBase<Odin3DofModel> {
  static constexpr std::string_view kName = "fossen-odin3dof";
  static constexpr int kParams = Odin3Dof::kParams, kYawInput = Odin3Dof::kYawInput;
  static constexpr bool kAccelerationResidual = false;  // tau is measured: residual in forces
  static constexpr int kFixedParam = -1;                // none
  static constexpr std::array<std::string_view, kInputs> kInputNames = Odin3Dof::kInputNames;
  static constexpr std::array<std::string_view, kParams> kParamNames = Odin3Dof::kParamNames;
  static constexpr std::array<double, kParams> kDefaultParams = Odin3Dof::kDefaultParams;
  static constexpr std::array<ParamGroup, kParams> kParamGroups = Odin3Dof::kParamGroups;
  static constexpr std::array<double, kInputs> kInputMin = Odin3Dof::kInputMin;
  static constexpr std::array<double, kInputs> kInputMax = Odin3Dof::kInputMax;
  static constexpr std::array<double, kParams> kStart = {1000, 1000, 1000, 1, 1, 1, 1, 1, 1, 1};

  template <typename T>
  static void Forces(const T* /*p*/, const T* in, T* tau) {
    for (int i = 0; i < 3; ++i) tau[i] = in[i];
  }
  // tau_i written in channel names (contract section 5).
  static std::string ForceText(int i, const double* /*p*/) { return std::string(kInputNames[i]); }
};

struct WaterjetModel : FossenModelBase<WaterjetModel> {
  static constexpr std::string_view kName = "fossen-waterjet";
  static constexpr int kParams = 13, kYawInput = 1;
  static constexpr bool kAccelerationResidual = true;  // tau is not measured
  static constexpr int kFixedParam = 0;                // m11 fixes the scale
  static constexpr std::array<std::string_view, kInputs> kInputNames = {"throttle", "nozzle",
                                                                        "bucket"};
  static constexpr std::array<std::string_view, kParams> kParamNames = {
      "m11", "m22", "m33", "Xu", "Xuu", "Yv", "Yvv", "Nv", "Nr", "Nrr", "Tx", "Ty", "Tn"};
  static constexpr std::array<double, kParams> kStart = {5000, 5000, 20000, 50,    243,  200, 2000,
                                                         1281, 1281, 2975,  10000, 2000, 8000};
  static constexpr std::array<double, kParams> kDefaultParams = kStart;
  static constexpr std::array<ParamGroup, kParams> kParamGroups = {
      ParamGroup::kInertia, ParamGroup::kInertia, ParamGroup::kInertia, ParamGroup::kDamping,
      ParamGroup::kDamping, ParamGroup::kDamping, ParamGroup::kDamping, ParamGroup::kDamping,
      ParamGroup::kDamping, ParamGroup::kDamping, ParamGroup::kOther,   ParamGroup::kOther,
      ParamGroup::kOther};
  static constexpr std::array<double, kInputs> kInputMin = {0.0, -0.4712, -1.0};
  static constexpr std::array<double, kInputs> kInputMax = {1.0, 0.4712, 1.0};

  template <typename T>
  static void Forces(const T* p, const T* in, T* tau) {
    const T rpm = T(0.2) + T(0.8) * in[0];
    const T thrust = rpm * rpm;
    tau[0] = p[10] * thrust * in[2];
    tau[1] = -p[11] * thrust * in[1];
    tau[2] = p[12] * thrust * in[1];
  }
  static std::string ForceText(int i, const double* p) {
    const std::string thrust = "(0.2 + 0.8*throttle)*(0.2 + 0.8*throttle)";
    if (i == 0) return FormatNumber(p[10]) + "*" + thrust + "*bucket";
    if (i == 1) return "-" + FormatNumber(p[11]) + "*" + thrust + "*nozzle";
    return FormatNumber(p[12]) + "*" + thrust + "*nozzle";
  }
};

}  // namespace usvid::fossen
