// Fossen 3-DOF vessel with Odin's numbers, vessel `odin3dof` (docs/model.md#odin3dof, the
// reference report's eq. 3.12 with D22 on |v_r|):
//   eta' = R(psi) nu,   M nu' + C(nu) nu + D(nu_r) nu_r = tau,   nu_r = nu - nu_c,
//   M = diag(m11, m22, m33),  C(nu) = [[0, 0, -m22 v], [0, 0, m11 u], [m22 v, -m11 u, 0]],
//   D(nu_r) = [[Xu + Xuu|u_r|, 0, 0], [0, Yv + Yvv|v_r|, 0], [0, Nv, Nr + Nrr|r|]],
//   nu_c = R(psi)^T [current_north, current_east, 0].
// States north, east [m], psi [rad], u, v [m/s], r [rad/s]; inputs tau_x, tau_y [N],
// tau_n [N m]. Defaults: m11 = m22 = 4935 kg, m33 = 20928 kg m^2, Xu = 50, Xuu = 243,
// Yv = 200, Yvv = 2000, Nv = 1281, Nr = 1281, Nrr = 2975 (SI).
#pragma once

#include <cmath>

#include "simulators/vessel.h"

namespace usvid {

struct Odin3Dof {
  static constexpr std::string_view kName = "odin3dof";
  static constexpr int kStates = 6, kInputs = 3, kParams = 10;
  static constexpr std::array<std::string_view, kStates> kStateNames = {"north", "east", "psi",
                                                                        "u",     "v",    "r"};
  static constexpr std::array<std::string_view, kInputs> kInputNames = {"tau_x", "tau_y", "tau_n"};
  static constexpr std::array<std::string_view, kParams> kParamNames = {
      "m11", "m22", "m33", "Xu", "Xuu", "Yv", "Yvv", "Nv", "Nr", "Nrr"};
  static constexpr std::array<double, kParams> kDefaultParams = {
      4935.0, 4935.0, 20928.0, 50.0, 243.0, 200.0, 2000.0, 1281.0, 1281.0, 2975.0};
  static constexpr std::array<ParamGroup, kParams> kParamGroups = {
      ParamGroup::kInertia,    ParamGroup::kInertia,    ParamGroup::kInertia,
      ParamGroup::kResistance, ParamGroup::kResistance,  // Xu, Xuu
      ParamGroup::kDamping,    ParamGroup::kDamping,    ParamGroup::kDamping,
      ParamGroup::kDamping,    ParamGroup::kDamping};
  // Surge force for 0 to about 14 m/s; the sway force and yaw moment two waterjets of about
  // 10 kN each give at 27 deg of nozzle, 3.8 m behind the centre of gravity.
  static constexpr std::array<double, kInputs> kInputMin = {0.0, -5000.0, -40000.0};
  static constexpr std::array<double, kInputs> kInputMax = {50000.0, 5000.0, 40000.0};
  static constexpr int kYawInput = 2, kThrustInput = 0, kRateState = 5, kHeadingState = 2;

  // Parameter indices, in kParamNames order.
  enum Param { kM11, kM22, kM33, kXu, kXuu, kYv, kYvv, kNv, kNr, kNrr };

  // The hull's forces h = C(nu) nu + D(nu_r) nu_r, so that M nu' = tau - h: Coriolis on the
  // velocities u, v, r over ground, damping on u_r, v_r through the water. The one right-hand
  // side of this form, used by the simulator and by fossen-ceres's models.
  template <typename T>
  static void Hull(const T* p, const T& u, const T& v, const T& r, const T& u_r, const T& v_r,
                   T* h) {
    using std::abs;
    h[0] = -p[kM22] * v * r + (p[kXu] + p[kXuu] * abs(u_r)) * u_r;
    h[1] = p[kM11] * u * r + (p[kYv] + p[kYvv] * abs(v_r)) * v_r;
    h[2] = (p[kM22] - p[kM11]) * u * v + p[kNv] * v_r + (p[kNr] + p[kNrr] * abs(r)) * r;
  }

  template <typename T>
  static void Derivative(const T* x, const T* tau, const T* p, const Environment<T>& env, T* dx) {
    using std::cos;
    using std::sin;
    const T& psi = x[2];
    const T& u = x[3];
    const T& v = x[4];
    const T& r = x[5];
    const T c = cos(psi);
    const T s = sin(psi);
    const T u_r = u - (c * env.current_north + s * env.current_east);
    const T v_r = v - (-s * env.current_north + c * env.current_east);
    T h[3];
    Hull(p, u, v, r, u_r, v_r, h);
    dx[0] = c * u - s * v;
    dx[1] = s * u + c * v;
    dx[2] = r;
    dx[3] = (tau[0] - h[0]) / p[kM11];
    dx[4] = (tau[1] - h[1]) / p[kM22];
    dx[5] = (tau[2] - h[2]) / p[kM33];
  }
};

}  // namespace usvid
