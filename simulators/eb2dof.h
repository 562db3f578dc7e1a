// Eriksen-Breivik 2-DOF high-speed model, vessel `eb2dof` (docs/model.md#eb2dof; Eriksen &
// Breivik 2017, reference report eq. 2.4-2.6). State x = [U r] (speed over ground [m/s], rate of
// turn [rad/s]), input tau = [throttle, nozzle] ([0,1] or [-1,1]; [rad]):
//   M(x) x' + sigma(x) = tau,   M(x) = diag(m_U(x), m_r(x)),
//   m_U = mU0 + mU1 U,                      m_r = mr0 + mr1 U,
//   sigma_U = sU1 U + sU2 U^2 + sU3 U^3 + sUr r^2,
//   sigma_r = sr1 r + srU U r + sr3 r^3,
// with sigma evaluated at the speed through the water U_r = U - (c_n cos chi + c_e sin chi).
// Kinematics (beta' taken as 0): chi' = r, north' = U cos chi, east' = U sin chi.
// States north, east [m], chi [rad], U [m/s], r [rad/s]. The default coefficients give a top
// speed of about 15 m/s at throttle 1, a surge time constant of about 5 s at 10 m/s and a yaw
// time constant of about 1 s; they are a model form for identification studies, not a hull.
#pragma once

#include <cmath>

#include "simulators/vessel.h"

namespace usvid {

struct Eb2Dof {
  static constexpr std::string_view kName = "eb2dof";
  static constexpr int kStates = 5, kInputs = 2, kParams = 11;
  static constexpr std::array<std::string_view, kStates> kStateNames = {"north", "east", "chi", "U",
                                                                        "r"};
  static constexpr std::array<std::string_view, kInputs> kInputNames = {"throttle", "nozzle"};
  static constexpr std::array<std::string_view, kParams> kParamNames = {
      "mU0", "mU1", "mr0", "mr1", "sU1", "sU2", "sU3", "sUr", "sr1", "srU", "sr3"};
  static constexpr std::array<double, kParams> kDefaultParams = {
      0.3, 0.01, 1.2, 0.05, 0.02, 0.0015, 1e-4, 0.5, 0.5, 0.15, 2.0};
  static constexpr std::array<ParamGroup, kParams> kParamGroups = {
      ParamGroup::kInertia,    ParamGroup::kInertia,    ParamGroup::kInertia,
      ParamGroup::kInertia,    ParamGroup::kResistance, ParamGroup::kResistance,  // sU1, sU2
      ParamGroup::kResistance, ParamGroup::kDamping,    ParamGroup::kDamping,     // sU3
      ParamGroup::kDamping,    ParamGroup::kDamping};
  static constexpr std::array<double, kInputs> kInputMin = {0.0, -0.4712};
  static constexpr std::array<double, kInputs> kInputMax = {1.0, 0.4712};
  static constexpr int kYawInput = 1, kThrustInput = 0, kRateState = 4, kHeadingState = 2;

  // Parameter indices, in kParamNames order.
  enum Param { kMU0, kMU1, kMr0, kMr1, kSU1, kSU2, kSU3, kSUr, kSr1, kSrU, kSr3 };

  template <typename T>
  static void Derivative(const T* x, const T* tau, const T* p, const Environment<T>& env, T* dx) {
    using std::cos;
    using std::sin;
    const T& chi = x[2];
    const T& U = x[3];
    const T& r = x[4];
    const T c = cos(chi);
    const T s = sin(chi);
    const T U_r = U - (c * env.current_north + s * env.current_east);
    const T m_U = p[kMU0] + p[kMU1] * U;
    const T m_r = p[kMr0] + p[kMr1] * U;
    const T sigma_U =
        p[kSU1] * U_r + p[kSU2] * U_r * U_r + p[kSU3] * U_r * U_r * U_r + p[kSUr] * r * r;
    const T sigma_r = p[kSr1] * r + p[kSrU] * U * r + p[kSr3] * r * r * r;
    dx[0] = U * c;
    dx[1] = U * s;
    dx[2] = r;
    dx[3] = (tau[0] - sigma_U) / m_U;
    dx[4] = (tau[1] - sigma_r) / m_r;
  }
};

}  // namespace usvid
