// The MMG standard model's forces and motion (Yasukawa & Yoshimura 2015, "Introduction of MMG
// standard method for ship maneuvering predictions", J Mar Sci Technol 20, 37-52), written once
// for every vessel of its form: the compiled-in kvlcc2 (simulators/kvlcc2.h) and a vessel read
// from a file (simulators/mmg.h, docs/model.md#vessel-files). The equations are given in
// simulators/kvlcc2.h's header comment; here the particulars (lengths, areas, positions) are
// arguments instead of constants, and the 37 coefficients come in the order of
// MmgCoefficients::kNames.
//
// The particulars are doubles: no fit differentiates through a hull's length. The coefficients
// are the scalar T (double or ceres::Jet).
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "simulators/scalar.h"
#include "simulators/vessel.h"

namespace usvid {

// The fixed geometry of an MMG vessel. SI units; positions are fractions of L from midship,
// positive ahead.
struct MmgParticulars {
  double rho;      // [kg/m^3] water density
  double L;        // [m] length between perpendiculars
  double d;        // [m] draft
  double x_G;      // [m] centre of gravity ahead of midship
  double D_P;      // [m] propeller diameter
  double A_R;      // [m^2] rudder area
  double H_R;      // [m] rudder span
  double x_P;      // [-] propeller position x'_P
  double x_R;      // [-] rudder position x'_R
  double kappa;    // [-] propeller slipstream on the rudder
  double f_alpha;  // [-] rudder lift gradient
};

// The 37 coefficients of the MMG standard model, in one order for every vessel of its form.
struct MmgCoefficients {
  static constexpr int kCount = 37;
  // clang-format off
  static constexpr std::array<std::string_view, kCount> kNames = {
      "m", "I_zG", "m_x", "m_y", "J_z",
      "R_0", "X_vv", "X_vr", "X_rr", "X_vvvv",
      "Y_v", "Y_r", "Y_vvv", "Y_vvr", "Y_vrr", "Y_rrr",
      "N_v", "N_r", "N_vvv", "N_vvr", "N_vrr", "N_rrr",
      "t_P", "w_P0", "k_0", "k_1", "k_2", "C_1", "C_2_pos", "C_2_neg",
      "t_R", "a_H", "x_H", "gamma_R_neg", "gamma_R_pos", "l_R", "epsilon"};
  // clang-format on
  // Inertia (m, I_zG and the added masses) scale the mass matrix together; the hull's twenty
  // coefficients are its damping, R_0 among them the resistance; the rest are "other".
  static constexpr ParamGroup Group(int i) {
    return i < 5    ? ParamGroup::kInertia
           : i == 5 ? ParamGroup::kResistance
           : i < 22 ? ParamGroup::kDamping
                    : ParamGroup::kOther;
  }
  enum Param {
    kM,
    kIzG,
    kMx,
    kMy,
    kJz,
    kR0,
    kXvv,
    kXvr,
    kXrr,
    kXvvvv,
    kYv,
    kYr,
    kYvvv,
    kYvvr,
    kYvrr,
    kYrrr,
    kNv,
    kNr,
    kNvvv,
    kNvvr,
    kNvrr,
    kNrrr,
    kTP,
    kWP0,
    kK0,
    kK1,
    kK2,
    kC1,
    kC2Pos,
    kC2Neg,
    kTR,
    kAH,
    kXH,
    kGammaRNeg,
    kGammaRPos,
    kLR,
    kEpsilon
  };
  static constexpr double kEps = 1e-6;  // [m/s] keeps U and J_P finite at rest
};

// Surge, sway and yaw forces [N, N, N m] of hull, propeller and rudder on relative velocities;
// delta in the MMG sign (positive turns to starboard), n the propeller's revolutions [1/s].
// `thrust(J_P, J_s, n)` gives K_T from the advance ratio behind the hull J_P = u (1 - w_P) / (n D)
// or in open water J_s = u / (n D): MmgForwardThrust for a propeller that turns ahead only.
template <typename T, typename Thrust>
void MmgForces(const T& u, const T& v, const T& r, const T& delta, const T& n, const T* p,
               const MmgParticulars& s, Thrust&& thrust, T* f) {
  using C = MmgCoefficients;
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::exp;
  using std::sin;
  using std::sqrt;
  constexpr double kEps = C::kEps;
  const double L = s.L, d = s.d, q = 0.5 * s.rho;
  const T U = sqrt(u * u + v * v + T(kEps * kEps));
  const T vn = v / U, rn = r * L / U;
  const T U2 = U * U;
  const T vn2 = vn * vn, rn2 = rn * rn;
  const T X_H = q * L * d * U2 *
                (-p[C::kR0] + p[C::kXvv] * vn2 + p[C::kXvr] * vn * rn + p[C::kXrr] * rn2 +
                 p[C::kXvvvv] * vn2 * vn2);
  const T Y_H = q * L * d * U2 *
                (p[C::kYv] * vn + p[C::kYr] * rn + p[C::kYvvv] * vn2 * vn + p[C::kYvvr] * vn2 * rn +
                 p[C::kYvrr] * vn * rn2 + p[C::kYrrr] * rn2 * rn);
  const T N_H = q * L * L * d * U2 *
                (p[C::kNv] * vn + p[C::kNr] * rn + p[C::kNvvv] * vn2 * vn + p[C::kNvvr] * vn2 * rn +
                 p[C::kNvrr] * vn * rn2 + p[C::kNrrr] * rn2 * rn);

  // Propeller.
  const double D = s.D_P;
  const T beta = atan2(-v, u);
  const T beta_p = beta - s.x_P * rn;
  const T c2 = ValueOf(beta_p) > 0 ? p[C::kC2Pos] : p[C::kC2Neg];
  const T w_p =
      1.0 - (1.0 - p[C::kWP0]) * (1.0 + (1.0 - exp(-p[C::kC1] * abs(beta_p))) * (c2 - 1.0));
  const T u_p = u * (1.0 - w_p);
  const T nd = n * D + T(kEps);
  const T J = u_p / nd;
  // Astern (n < 0) the thrust coefficient is an effective one, the thrust deduction included.
  const T K_T = thrust(J, u / nd, n);
  const T X_P = (ValueOf(n) < 0 ? T(1.0) : 1.0 - p[C::kTP]) * s.rho * n * n * D * D * D * D * K_T;

  // Rudder. 8 K_T / (pi J^2) written as 8 K_T (n D)^2 / (pi u_p^2), kept >= -1.
  const double eta = D / s.H_R;
  T load = 8.0 * K_T * nd * nd / (3.14159265358979323846 * (u_p * u_p + T(kEps * kEps)));
  if (ValueOf(load) < -1.0) load = T(-1.0);
  const T slip = 1.0 + s.kappa * (sqrt(1.0 + load + T(kEps)) - 1.0);
  const T u_r = p[C::kEpsilon] * u_p * sqrt(eta * slip * slip + (1.0 - eta));
  const T beta_r = beta - p[C::kLR] * rn;
  const T gamma = ValueOf(beta_r) < 0 ? p[C::kGammaRNeg] : p[C::kGammaRPos];
  const T v_r = U * gamma * beta_r;
  const T alpha = delta - atan2(v_r, u_r);
  const T F_N = q * s.A_R * (u_r * u_r + v_r * v_r) * s.f_alpha * sin(alpha);
  const T X_R = -(1.0 - p[C::kTR]) * F_N * sin(delta);
  const T Y_R = -(1.0 + p[C::kAH]) * F_N * cos(delta);
  const T N_R = -(s.x_R * L + p[C::kAH] * p[C::kXH] * L) * F_N * cos(delta);

  f[0] = X_H + X_P + X_R;
  f[1] = Y_H + Y_R;
  f[2] = N_H + N_R;
}

// K_T = k_0 + k_1 J_P + k_2 J_P^2: the open-water curve of a propeller turning ahead.
template <typename T>
struct MmgForwardThrust {
  const T* p;
  T operator()(const T& J, const T& /*J_s*/, const T& /*n*/) const {
    using C = MmgCoefficients;
    return p[C::kK0] + p[C::kK1] * J + p[C::kK2] * J * J;
  }
};

// The motion of an MMG vessel about midship (Yasukawa & Yoshimura eq. 4), with the current:
// the hydrodynamics see nu_r = nu - R(psi)^T [current_north, current_east, 0]. `extra` adds
// forces that do not come from the water (wind: simulators/mmg.h) to f before the motion.
// States north, east, psi, u, v, r.
template <typename T, typename Thrust, typename Extra>
void MmgMotion(const T* x, const T& delta_mmg, const T& n, const T* p, const MmgParticulars& s,
               const Environment<T>& env, Thrust&& thrust, Extra&& extra, T* dx) {
  using C = MmgCoefficients;
  using std::cos;
  using std::sin;
  const T& psi = x[2];
  const T& u = x[3];
  const T& v = x[4];
  const T& r = x[5];
  const T c = cos(psi);
  const T sn = sin(psi);
  const T u_c = c * env.current_north + sn * env.current_east;
  const T v_c = -sn * env.current_north + c * env.current_east;
  const T u_r = u - u_c;
  const T v_r = v - v_c;
  T f[3];
  MmgForces(u_r, v_r, r, delta_mmg, n, p, s, thrust, f);
  extra(f);

  const double L = s.L, d = s.d, q = 0.5 * s.rho;
  const T& m = p[C::kM];
  const T m11 = m + p[C::kMx] * q * L * L * d;
  const T m22 = m + p[C::kMy] * q * L * L * d;
  const T m33 = p[C::kIzG] + s.x_G * s.x_G * m + p[C::kJz] * q * L * L * L * L * d;
  const T mx = s.x_G * m;
  // [m22 mx; mx m33] [v_r'; r'] = [Y - m11 u_r r; N - mx u_r r].
  const T b1 = f[1] - m11 * u_r * r;
  const T b2 = f[2] - mx * u_r * r;
  const T det = m22 * m33 - mx * mx;
  const T dv_r = (m33 * b1 - mx * b2) / det;
  const T dr = (m22 * b2 - mx * b1) / det;
  const T du_r = (f[0] + m22 * v_r * r + mx * r * r) / m11;

  dx[0] = c * u - sn * v;
  dx[1] = sn * u + c * v;
  dx[2] = r;
  dx[3] = du_r + r * v_c;
  dx[4] = dv_r - r * u_c;
  dx[5] = dr;
}

}  // namespace usvid
