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
//    13 parameters by one factor leaves the model unchanged, so fits hold m11 at its start;
//  - RudderModel: inputs delta [rad] (ITTC sign: positive turns to port) and rev [rev/min] of a
//    single-screw ship with its rudder in the propeller race (kvlcc2), 13 parameters:
//      n = rev / 60,  tau_x = Tx n^2,  tau_y = Ty n^2 delta,  tau_n = -Tn n^2 delta
//    (thrust and the rudder's inflow both grow like n^2 at a given advance ratio). A ship's
//    Munk moment (m22 - m11) u v outweighs its hull's yaw damping in sway, so Nv may be negative
//    (kSignedParam); m11 is held as for the waterjet model;
//  - RudderRpsModel: the same map for a vessel file's ship (simulators/mmg.h), inputs delta [rad]
//    in the file's sign and n [1/s], which may reverse:
//      tau_x = Tx n |n|,  tau_y = Ty n^2 delta,  tau_n = Tn n^2 delta
//    with Ty and Tn of either sign (ITTC: Ty > 0, Tn < 0; MMG: the other way round). It has no
//    fixed starting values: fossen_method.cc scales RudderModel's (KVLCC2's) to the ship by
//    Froude's law (RudderRpsStart).
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
  static constexpr int kStates = 6;
  static constexpr int kSignedParam = -1;  // the parameter that may take either sign (-1: none)
  // Ceres stops when a step is this small relative to the parameter vector's norm.
  static constexpr double kParameterTolerance = 1e-12;
  static constexpr bool kNormaliseParams = false;  // fit p_i / |start_i| instead of p_i
  static constexpr std::array<std::string_view, kStates> kStateNames = Odin3Dof::kStateNames;
  static constexpr int kThrustInput = 0, kRateState = 5, kHeadingState = 2;
  // The thrust gains after odin3dof's parameters (Odin3Dof::Param), in the models that have them.
  enum ThrustGain { kTx = Odin3Dof::kParams, kTy, kTn };

  static constexpr bool kLinearEquationError = false;  // solve the equation error unbounded
  static constexpr double kFunctionTolerance = 0.0;     // Ceres stops no earlier than this
  static constexpr int kPenaltyResiduals = 0;  // prior residuals (JetForceModel's smoothness)
  static constexpr bool Signed(int i) { return i == Model::kSignedParam; }
  // The smallest physical value of an unsigned parameter (0: only positive).
  static constexpr double MinValue(int /*i*/) { return 0.0; }

  // Odin3Dof's dynamics driven by tau(in; p); p starts with odin3dof's 10 parameters.
  template <typename T>
  static void Derivative(const T* x, const T* in, const T* p, const Environment<T>& env, T* dx) {
    T tau[3];
    Model::Forces(p, in, tau);
    Odin3Dof::Derivative<T>(x, tau, p, env, dx);
  }
  // C(nu) nu + D(nu) nu of odin3dof's form, in calm water: M nu' = tau - h.
  template <typename T>
  static void Hull(const T* p, const T& u, const T& v, const T& r, const T* /*in*/, T* h) {
    Odin3Dof::Hull(p, u, v, r, u, v, h);
  }
  template <typename T>
  static void Penalty(const T* /*p*/, T* /*res*/) {}
};

struct Odin3DofModel : FossenModelBase<Odin3DofModel> {
  static constexpr std::string_view kName = "fossen-odin3dof";
  static constexpr int kInputs = 3;
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
  // tau_i written in channel names (docs/data.md#modeljson).
  static std::string ForceText(int i, const double* /*p*/) { return std::string(kInputNames[i]); }
};

struct WaterjetModel : FossenModelBase<WaterjetModel> {
  static constexpr std::string_view kName = "fossen-waterjet";
  static constexpr int kInputs = 3;
  static constexpr int kParams = 13, kYawInput = 1;
  static constexpr bool kAccelerationResidual = true;  // tau is not measured
  static constexpr int kFixedParam = Odin3Dof::kM11;  // m11 fixes the scale
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
    tau[0] = p[kTx] * thrust * in[2];
    tau[1] = -p[kTy] * thrust * in[1];
    tau[2] = p[kTn] * thrust * in[1];
  }
  static std::string ForceText(int i, const double* p) {
    const std::string thrust = "(0.2 + 0.8*throttle)*(0.2 + 0.8*throttle)";
    if (i == 0) return FormatNumber(p[kTx]) + "*" + thrust + "*bucket";
    if (i == 1) return "-" + FormatNumber(p[kTy]) + "*" + thrust + "*nozzle";
    return FormatNumber(p[kTn]) + "*" + thrust + "*nozzle";
  }
};

struct RudderModel : FossenModelBase<RudderModel> {
  static constexpr std::string_view kName = "fossen-rudder";
  static constexpr int kInputs = 2, kParams = 13, kYawInput = 0;
  static constexpr bool kAccelerationResidual = true;  // tau is not measured
  static constexpr int kFixedParam = Odin3Dof::kM11;  // m11 fixes the scale
  static constexpr int kSignedParam = Odin3Dof::kNv;  // Nv
  // Parameters span 1e4 to 1e13: fitted relative to their starts.
  static constexpr bool kNormaliseParams = true;
  static constexpr std::array<std::string_view, kInputs> kInputNames = {"delta", "rev"};
  static constexpr std::array<std::string_view, kParams> kParamNames = WaterjetModel::kParamNames;
  // KVLCC2 at 15.5 kn from its MMG coefficients (simulators/kvlcc2.h): m + m_x, m + m_y,
  // I_zG + x_G^2 m + J_z; q L d U |Y'_v| and friends; thrust and rudder force at 91.7 rpm.
  static constexpr std::array<double, kParams> kStart = {
      3.44e8, 5.64e8, 3.29e12, 1e4, 7.5e4, 8.6e6, 1e7, -5e8, 1.4e11, 1e13, 1.4e6, 5.5e6, 1.1e9};
  static constexpr std::array<double, kParams> kDefaultParams = kStart;
  static constexpr std::array<ParamGroup, kParams> kParamGroups = WaterjetModel::kParamGroups;
  static constexpr std::array<double, kInputs> kInputMin = {-0.6109, 0.0};
  static constexpr std::array<double, kInputs> kInputMax = {0.6109, 150.0};

  template <typename T>
  static void Forces(const T* p, const T* in, T* tau) {
    const T n = in[1] / 60.0;
    const T n2 = n * n;
    tau[0] = p[kTx] * n2;
    tau[1] = p[kTy] * n2 * in[0];
    tau[2] = -p[kTn] * n2 * in[0];
  }
  static std::string ForceText(int i, const double* p) {
    const std::string n2 = "(rev/60)*(rev/60)";
    if (i == 0) return FormatNumber(p[kTx]) + "*" + n2;
    if (i == 1) return FormatNumber(p[kTy]) + "*" + n2 + "*delta";
    return "-" + FormatNumber(p[kTn]) + "*" + n2 + "*delta";
  }
};

// The rudder-propeller map of a vessel file's ship: propeller revolutions per second, four
// quadrants, and the rudder's sign left to the fit (above).
struct RudderRpsModel : FossenModelBase<RudderRpsModel> {
  static constexpr std::string_view kName = "fossen-rudder-rps";
  static constexpr int kInputs = 2, kParams = 13, kYawInput = 0;
  static constexpr bool kAccelerationResidual = true;  // tau is not measured
  static constexpr int kFixedParam = Odin3Dof::kM11;   // m11 fixes the scale
  static constexpr bool kNormaliseParams = true;
  static constexpr std::array<std::string_view, kInputs> kInputNames = {"delta", "n"};
  static constexpr std::array<std::string_view, kParams> kParamNames = WaterjetModel::kParamNames;
  // Placeholders: a fit always starts from RudderRpsStart (FossenOptions::start).
  static constexpr std::array<double, kParams> kStart = RudderModel::kStart;
  static constexpr std::array<double, kParams> kDefaultParams = kStart;
  static constexpr std::array<ParamGroup, kParams> kParamGroups = WaterjetModel::kParamGroups;
  static constexpr std::array<double, kInputs> kInputMin = {-1.5708, -100.0};
  static constexpr std::array<double, kInputs> kInputMax = {1.5708, 100.0};
  static constexpr bool Signed(int i) { return i == Odin3Dof::kNv || i == kTy || i == kTn; }

  template <typename T>
  static void Forces(const T* p, const T* in, T* tau) {
    using std::abs;
    const T& n = in[1];
    tau[0] = p[kTx] * n * abs(n);
    tau[1] = p[kTy] * n * n * in[0];
    tau[2] = p[kTn] * n * n * in[0];
  }
  static std::string ForceText(int i, const double* p) {
    if (i == 0) return FormatNumber(p[kTx]) + "*n*abs(n)";
    return FormatNumber(p[i == 1 ? kTy : kTn]) + "*n*n*delta";
  }
};

}  // namespace usvid::fossen
