// KVLCC2 tanker, vessel `kvlcc2`: the MMG standard model of Yasukawa & Yoshimura (2015,
// "Introduction of MMG standard method for ship maneuvering predictions", J Mar Sci Technol 20,
// 37-52), with its published KVLCC2 hull, propeller and rudder coefficients, at full scale
// (Lpp 320 m). Sources and measured behaviour: docs/vessels/kvlcc2.md. SI units, radians.
//
// States  north, east [m], psi [rad], u, v [m/s] (surge, and sway at midship), r [rad/s].
// Inputs  delta [rad] (rudder angle, ITTC sign as in the MARIN files: positive is trailing edge
//         to port and turns the ship to port), rev [rev/min] (propeller). The MMG equations
//         below use the Japanese sign, delta_MMG = -delta (positive turns to starboard).
// Motion  about midship, centre of gravity x_G ahead of it (Yasukawa & Yoshimura eq. 4):
//   (m + m_x) u' - (m + m_y) v r - x_G m r^2           = X_H + X_R + X_P
//   (m + m_y) v' + x_G m r' + (m + m_x) u r            = Y_H + Y_R
//   (I_zG + x_G^2 m + J_z) r' + x_G m v' + x_G m u r   = N_H + N_R
//   with m_x = m'_x q L^2 d,  m_y = m'_y q L^2 d,  J_z = J'_z q L^4 d,  q = rho / 2.
// Hull    U = sqrt(u^2 + v^2), v' = v / U, r' = r L / U:
//   X_H = q L d U^2 (-R'_0 + X'_vv v'^2 + X'_vr v' r' + X'_rr r'^2 + X'_vvvv v'^4)
//   Y_H = q L d U^2 (Y'_v v' + Y'_r r' + Y'_vvv v'^3 + Y'_vvr v'^2 r' + Y'_vrr v' r'^2 + Y'_rrr
//   r'^3) N_H = q L^2 d U^2 (N'_v v' + ... + N'_rrr r'^3)   (same six terms)
// Propeller  n = rev / 60, beta = atan2(-v, u), beta_P = beta - x'_P r',
//   w_P = 1 - (1 - w_P0)(1 + (1 - exp(-C_1 |beta_P|))(C_2 - 1)),  C_2 = C_2+ (beta_P > 0) or C_2-,
//   J_P = u (1 - w_P) / (n D_P),  K_T = k_0 + k_1 J_P + k_2 J_P^2,
//   X_P = (1 - t_P) rho n^2 D_P^4 K_T.
// Rudder  u_R = eps u (1 - w_P) sqrt(eta (1 + kappa (sqrt(1 + 8 K_T / (pi J_P^2)) - 1))^2 + 1 -
// eta),
//   eta = D_P / H_R,  beta_R = beta - l'_R r',  v_R = U gamma_R beta_R
//   (gamma_R = gamma_R- for beta_R < 0, gamma_R+ otherwise),  alpha_R = delta - atan2(v_R, u_R),
//   F_N = q A_R (u_R^2 + v_R^2) f_alpha sin(alpha_R),
//   X_R = -(1 - t_R) F_N sin(delta),  Y_R = -(1 + a_H) F_N cos(delta),
//   N_R = -(x_R + a_H x_H) F_N cos(delta),  x_R = x'_R L,  x_H = x'_H L.
// Current  the hydrodynamics see nu_r = nu - R(psi)^T [current_north, current_east, 0]; the
//   equations above give nu_r', and u' = u_r' + r v_c, v' = v_r' - r u_c (as odin-hs).
// Inertia parameters (m, I_zG, m'_x, m'_y, J'_z) scale the whole mass matrix together; damping
// parameters are the hull's twenty coefficients, R'_0 among them the resistance; propeller and
// rudder coefficients are "other".
#pragma once

#include <cmath>
#include <string_view>

#include "simulators/mmg_forces.h"
#include "simulators/vessel.h"

namespace usvid {

struct Kvlcc2 : MmgCoefficients {
  static constexpr std::string_view kName = "kvlcc2";
  static constexpr int kStates = 6, kInputs = 2, kParams = MmgCoefficients::kCount;
  static constexpr std::array<std::string_view, kStates> kStateNames = {"north", "east", "psi",
                                                                        "u",     "v",    "r"};
  static constexpr std::array<std::string_view, kInputs> kInputNames = {"delta", "rev"};
  // Rudder hard over at 35 deg; the propeller turns ahead only, up to 150 rpm (the MARIN
  // free-running tests ran at 91.7 rpm, full scale).
  static constexpr std::array<double, kInputs> kInputMin = {-0.6109, 0.0};
  static constexpr std::array<double, kInputs> kInputMax = {0.6109, 150.0};
  static constexpr std::array<double, kInputs> kNeutralInput = {0.0, 91.7};
  static constexpr int kYawInput = 0, kThrustInput = 1, kRateState = 5, kHeadingState = 2;
  static constexpr double kYawSign = -1.0;  // positive delta turns to port (ITTC)
  // Steering gear of the MARIN tests, 2.32 deg/s at full scale (SIMMAN 2020 case 1.2) [rad/s]:
  // zig-zag and turning maneuvers move the rudder no faster (the inputs themselves are the rudder
  // angle).
  static constexpr double kYawRateLimit = 2.32 * 3.14159265358979323846 / 180.0;

  // Fixed particulars, full scale (Yasukawa & Yoshimura 2015 table 1).
  static constexpr double kRho = 1025.0;              // [kg/m^3]
  static constexpr double kLength = 320.0;            // [m] Lpp
  static constexpr double kDraft = 20.8;              // [m] d
  static constexpr double kXG = 11.2;                 // [m] centre of gravity ahead of midship
  static constexpr double kPropellerDiameter = 9.86;  // [m] D_P
  static constexpr double kRudderArea = 112.5;        // [m^2] A_R
  static constexpr double kRudderSpan = 15.80;        // [m] H_R
  static constexpr double kXPropeller = -0.48;        // [-] x'_P
  static constexpr double kXRudder = -0.5;            // [-] x'_R
  // What `identify --method refit` fits unless told otherwise: the resistance and the linear
  // hull derivatives. The zig-zag and turning tests hardly excite the cubic terms: freeing
  // them lets the fit trade one against another (docs/real-data.md).
  static constexpr std::array<std::string_view, 5> kRefitParams = {"R_0", "Y_v", "Y_r", "N_v",
                                                                   "N_r"};
  static constexpr bool kSpeedScaledForces = true;  // MMG: forces 1/2 rho L d U^2 X'(v', r')
  static constexpr double kRunInS = 7200.0;         // [s] from rest to steady speed (closed_loop.h)

  static constexpr std::array<std::string_view, kParams> kParamNames = MmgCoefficients::kNames;
  static constexpr std::array<double, kParams> kDefaultParams = {
      // --- inertia (table 1, 2): m = rho * 312600 m^3; I_zG = m (0.25 Lpp)^2 ---
      320415000.0, 2.0506560e12, 0.022, 0.223, 0.011,
      // --- hull resistance and surge (table 3, non-dimensional) ---
      0.022, -0.040, 0.002, 0.011, 0.771,
      // --- hull sway ---
      -0.315, 0.083, -1.607, 0.379, -0.391, 0.008,
      // --- hull yaw ---
      -0.137, -0.049, -0.030, -0.294, 0.055, -0.013,
      // --- propeller (table 4): thrust deduction, wake, K_T polynomial, wake in drift ---
      0.220, 0.40, 0.2931, -0.2753, -0.1385, 2.0, 1.6, 1.1,
      // --- rudder (table 5); f_alpha is kFAlpha below, kappa kKappa ---
      0.387, 0.312, -0.464, 0.395, 0.640, -0.710, 1.09};
  static constexpr double kKappa = 0.50;    // [-] propeller slipstream on the rudder (table 5)
  static constexpr double kFAlpha = 2.747;  // [-] rudder lift slope, aspect ratio 1.827 (table 5)
  static constexpr std::array<ParamGroup, kParams> kParamGroups = [] {
    std::array<ParamGroup, kParams> g{};
    for (int i = 0; i < kParams; ++i) g[i] = MmgCoefficients::Group(i);
    return g;
  }();
  static constexpr MmgParticulars kParticulars{
      kRho,        kLength,  kDraft, kXG,    kPropellerDiameter, kRudderArea, kRudderSpan,
      kXPropeller, kXRudder, kKappa, kFAlpha};

  // Surge, sway and yaw forces [N, N, N m] of hull, propeller and rudder on relative velocities;
  // delta in the MMG sign (positive turns to starboard).
  template <typename T>
  static void Forces(const T& u, const T& v, const T& r, const T& delta, const T& rev, const T* p,
                     T* f) {
    MmgForces(u, v, r, delta, T(rev / 60.0), p, kParticulars, MmgForwardThrust<T>{p}, f);
  }

  static double FroudeNumber(double speed) { return speed / std::sqrt(9.81 * kLength); }

  template <typename T>
  static void Derivative(const T* x, const T* in, const T* p, const Environment<T>& env, T* dx) {
    MmgMotion(
        x, T(-in[0]), T(in[1] / 60.0), p, kParticulars, env, MmgForwardThrust<T>{p}, [](T*) {}, dx);
  }
};

}  // namespace usvid
