// High-speed twin-waterjet USV of Odin's size, vessel `odin-hs` (docs/model.md#odin-hs): one hull
// model for the displacement (Fn < 0.4), semi-displacement (0.4-1.1) and planing (> 1.1) regimes,
// driven by two Hamilton-type waterjets used as one (same rpm, nozzle and bucket on both).
// Model, parameter sources and measured behaviour: docs/vessels/odin-hs.md. SI units, radians.
//
// States  north, east [m], psi [rad], u, v [m/s], r [rad/s], rpm [rev/min] (jet shaft speed),
//         nozzle_angle [rad] and bucket_position [-] (applied; 1 ahead, 0 neutral, -1 astern).
// Inputs  throttle [0, 1], nozzle [rad, +-27 deg], bucket [-1, 1]. The transport delay
//         kTransportDelay is applied by the runner on the input path, not here.
// Regime  nu_r = nu - R(psi)^T [current_north, current_east, 0] = [u_r, v_r, r],
//         U = sqrt(u_r^2 + v_r^2 + eps^2), Fn = U / sqrt(g L), L = 10.5 m waterline length.
//         Share of the weight on dynamic lift (bow first only, s = (1 + tanh(u_r / 0.5)) / 2)
//           f = s Fn^4 / (Fn^4 + Fn_lift^4);  wetted fraction lambda = 1 - (1 - wetted_planing) f.
// Resistance [N]  R = R_f + (1 - f) R_wave psi(Fn / Fn_hump) + f R_plan,
//         R_f = 1/2 rho S0 lambda U^2 form_factor C_F,  C_F = 0.075 / (log10 Re - 2)^2 (ITTC-57),
//         Re = U lambda L / nu + 1e5,  psi(x) = 2 x^6 / (1 + x^6) (wave hump, 1 at Fn_hump).
//         Buoyancy-borne weight makes waves, lift-borne weight costs Delta tan(trim) = R_plan
//         (Savitzky 1964); the wave term fading as lift takes over is the resistance hump.
// Jets    per jet: Q = jet_flow_per_rpm rpm [m^3/s], V_j = Q / nozzle_area [m/s],
//         X_j = rho Q (g(b) V_j cos(delta) - (1 - wake_fraction) u_r)   (momentum thrust),
//         Y_j = -rho Q (V_j sin(delta) + v_r + x_j r)                    (steering + inlet),
//         N_j = x_j Y_j - y_j X_j,  jets at (x_j, y_j) = (-3.82, +-0.475) m,
//         g(b) = b ((1 + eta) + (1 - eta) tanh(b / 0.05)) / 2  (1 ahead, -eta astern).
// Hull    side-force centre x_p = x_lat_disp + (x_lat_plan - x_lat_disp) f,  v_p = v_r + x_p r,
//         c = Yuv lambda U,  k^2 = (lambda L)^2 / 12,  |a| := sqrt(a^2 + eps^2),
//         X_h = -R u_r / U,  Y_h = -c v_p - Yvv lambda |v_p| v_p,
//         N_h = x_p Y_h - (c k^2 + Nr) r - Nrr lambda^4 |r| r.
// Motion  m11 = m + Xud, m22 = m + Yvd lambda^3, m33 = Iz + Nrd lambda^3 (added mass ~ draft^2
//         x wetted length, both ~ lambda), Coriolis of rigid body + added mass on nu_r
//         (irrotational constant current, Fossen 2011 sec. 10.3):
//         m11 u_r' = m22 v_r r + X,  m22 v_r' = -m11 u_r r + Y,  m33 r' = -(m22 - m11) u_r v_r + N,
//         u' = u_r' + r v_c,  v' = v_r' - r u_c,  psi' = r,
//         north' = cos(psi) u - sin(psi) v,  east' = sin(psi) u + cos(psi) v.
// Actuators  y' = rate tanh((y_cmd - y) / (tau rate)) (first order, slew-limited),
//         rpm_cmd = 400 + 1600 throttle [rev/min].
#pragma once

#include <cmath>
#include <string_view>

#include "simulators/vessel.h"

namespace usvid {

struct OdinHs {
  static constexpr std::string_view kName = "odin-hs";
  static constexpr int kStates = 9, kInputs = 3, kParams = 28;
  static constexpr std::array<std::string_view, kStates> kStateNames = {
      "north", "east", "psi", "u", "v", "r", "rpm", "nozzle_angle", "bucket_position"};
  static constexpr std::array<std::string_view, kInputs> kInputNames = {"throttle", "nozzle",
                                                                        "bucket"};
  static constexpr std::array<double, kInputs> kInputMin = {0.0, -0.4712, -1.0};
  static constexpr std::array<double, kInputs> kInputMax = {1.0, 0.4712, 1.0};
  static constexpr std::array<double, kInputs> kNeutralInput = {0.0, 0.0, 1.0};
  static constexpr int kYawInput = 1, kThrustInput = 0, kRateState = 5, kHeadingState = 2;
  static constexpr bool kDerivesSpeedAndCourse = true;  // runner adds U and chi channels
  static constexpr double kTransportDelay = 0.2;        // [s] onboard computer to jets

  // Fixed configuration (not estimated).
  static constexpr double kGravity = 9.81;          // [m/s^2]
  static constexpr double kRho = 1025.0;            // [kg/m^3] sea water
  static constexpr double kNu = 1.19e-6;            // [m^2/s] sea water at 15 C (ITTC 2011)
  static constexpr double kLength = 10.5;           // [m] waterline length (Fn, Re, strips)
  static constexpr double kJetX = -3.82;            // [m] jets' longitudinal position
  static constexpr double kJetY = 0.475;            // [m] jets at +-kJetY
  static constexpr double kIdleRpm = 400.0;         // [rev/min] throttle 0
  static constexpr double kMaxRpm = 2000.0;         // [rev/min] throttle 1
  static constexpr double kEps = 1e-3;              // [m/s], [rad/s] smooth |.| and U at rest
  static constexpr double kBucketSmoothing = 0.05;  // [-] width of the ahead/astern switch
  static constexpr double kReynoldsFloor = 1e5;     // keeps the ITTC line finite at rest
  static constexpr double kAheadSmoothing = 0.5;    // [m/s] lift only when moving bow first

  // clang-format off
  static constexpr std::array<std::string_view, kParams> kParamNames = {
      "m", "Iz", "Xud", "Yvd", "Nrd",
      "form_factor", "R_wave", "R_plan", "Yuv", "Yvv", "Nr", "Nrr",
      "S0", "Fn_hump", "Fn_lift", "wetted_planing", "x_lat_disp", "x_lat_plan",
      "jet_flow_per_rpm", "nozzle_area", "wake_fraction", "astern_efficiency",
      "rpm_time_constant", "rpm_rate_max", "nozzle_time_constant", "nozzle_rate_max",
      "bucket_time_constant", "bucket_rate_max"};
  static constexpr std::array<double, kParams> kDefaultParams = {
      // --- inertia ---
      4935.0,    // m [kg]: Odin's mass, reference report eq. 3.12.
      20928.0,   // Iz [kg m^2]: report eq. 3.12; radius of gyration 2.06 m = 0.20 L (typical).
      250.0,     // Xud [kg]: surge added mass, 5 % of m (slender hull, Fossen 2011 sec. 6.4).
      2500.0,    // Yvd [kg]: sway added mass at rest: strips rho pi T^2 / 2 over L, T = 0.42 m,
                 //   x 0.85 for the fine bow (strip theory, Fossen 2011 sec. 6.4).
      14000.0,   // Nrd [kg m^2]: yaw added inertia at rest, Yvd L^2 / 12 x 0.6 (fine ends).
      // --- resistance and damping ---
      1.15,      // form_factor [-]: 1 + k on the ITTC-57 line incl. roughness, skeg and jet
                 //   intakes (1.1-1.2 for small craft, ITTC 2011 recommended procedures).
      3800.0,    // R_wave [N]: wave resistance at the hump if all weight were buoyancy-borne,
                 //   0.078 Delta (hump R/Delta of 0.1-0.13 in Series 62 / Savitzky-Brown 1976).
      2700.0,    // R_plan [N]: Delta tan(trim), trim 3.2 deg when planing (Savitzky 1964).
      1500.0,    // Yuv [kg/m]: side-force slope. Clarke (1983) rho pi T^2 / 2 (1 + 0.4 Cb B/T)
                 //   = 600 for T 0.42, B/T 6.2, Cb 0.45; x 2.5 for skeg, chines and jet intakes,
                 //   set so a full-speed turn drifts 7 deg (planing craft: 5-10 deg).
      2300.0,    // Yvv [kg/m]: cross-flow drag rho Cd L T / 2, Cd = 1.0, T = 0.42 m (Hoerner).
      3000.0,    // Nr [N m s]: speed-independent yaw damping, the only linear one at rest;
                 //   order of odin3dof's Nr + Nv (2562).
      80000.0,   // Nrr [N m s^2]: yaw cross-flow drag, strip integral rho Cd T L^4 / 64.
      // --- hull geometry, thrust, actuators ---
      22.0,      // S0 [m^2]: wetted area at rest, 0.8 L B for a hard-chine hull, B = 2.6 m.
      0.5,       // Fn_hump [-]: last wave hump, wave length 2 pi Fn^2 L = 1.6 L (ship theory).
      0.8,       // Fn_lift [-]: half the weight on dynamic lift, mid semi-displacement range.
      0.5,       // wetted_planing [-]: S / S0 when planing; Savitzky mean wetted length-beam
                 //   ratio 1.6 at 35 kn, beam 2.6 m, deadrise 18 deg gives 11 m^2 of 22.
      0.0,       // x_lat_disp [m]: side-force centre when displacing: bow lift forward and
                 //   skeg + intakes aft balance near the CG (directionally stable at rest).
      -1.0,      // x_lat_plan [m]: side-force centre when planing, half-way between the lift
                 //   centre (under the CG in trim equilibrium) and the wetted-bottom centroid
                 //   2 m aft (transom 4 m aft, wetted length 4.1 m); sets the top-speed turn.
      1.92e-4,   // jet_flow_per_rpm [m^3/s per rev/min]: 0.384 m^3/s per jet at 2000 rpm
                 //   (pump affinity law Q ~ n), jet/inlet speed ratio 0.65 at 35 kn.
      0.0148,    // nozzle_area [m^2]: 137 mm nozzle, so V_j = 26 m/s at 2000 rpm (above).
      0.05,      // wake_fraction [-]: inlet boundary-layer ingestion, 0.03-0.1 (ITTC 2005 jets).
      0.6,       // astern_efficiency [-]: astern / ahead thrust at bucket -1 (Hamilton, ~55-65%).
      0.6,       // rpm_time_constant [s]: engine + governor response near the set point.
      600.0,     // rpm_rate_max [rev/min per s]: idle to 99 % of full rpm in about 3.9 s.
      0.1,       // nozzle_time_constant [s]: hydraulic steering servo.
      0.4363,    // nozzle_rate_max [rad/s]: 25 deg/s, lock to lock (54 deg) in about 2 s.
      0.1,       // bucket_time_constant [s]: hydraulic reversing-bucket servo.
      1.0};      // bucket_rate_max [1/s]: full ahead to full astern (2 units) in 2 s.
  static constexpr std::array<ParamGroup, kParams> kParamGroups = {
      ParamGroup::kInertia, ParamGroup::kInertia, ParamGroup::kInertia, ParamGroup::kInertia,
      ParamGroup::kInertia,
      ParamGroup::kResistance, ParamGroup::kResistance, ParamGroup::kResistance,  // R(U)
      ParamGroup::kDamping, ParamGroup::kDamping, ParamGroup::kDamping, ParamGroup::kDamping,
      ParamGroup::kOther, ParamGroup::kOther, ParamGroup::kOther, ParamGroup::kOther,
      ParamGroup::kOther, ParamGroup::kOther, ParamGroup::kOther, ParamGroup::kOther,
      ParamGroup::kOther, ParamGroup::kOther, ParamGroup::kOther, ParamGroup::kOther,
      ParamGroup::kOther, ParamGroup::kOther, ParamGroup::kOther, ParamGroup::kOther};
  // Parameter indices, in kParamNames order.
  enum Param {
    kM, kIz, kXud, kYvd, kNrd,
    kFormFactor, kRWave, kRPlan, kYuv, kYvv, kNr, kNrr,
    kS0, kFnHump, kFnLift, kWettedPlaning, kXLatDisp, kXLatPlan,
    kJetFlowPerRpm, kNozzleArea, kWakeFraction, kAsternEfficiency,
    kRpmTau, kRpmRate, kNozzleTau, kNozzleRate, kBucketTau, kBucketRate};
  // clang-format on

  // Froude number on the waterline length.
  static double FroudeNumber(double speed) { return speed / std::sqrt(kGravity * kLength); }

  // Regime by Froude number (docs/model.md#speed-regimes).
  static constexpr std::string_view Regime(double fn) {
    return fn < 0.4 ? "displacement" : fn <= 1.1 ? "semi-displacement" : "planing";
  }

  // Share of the weight carried by dynamic lift, f in [0, 1).
  template <typename T>
  static T LiftShare(const T& speed, const T* p) {
    const T fn = speed / std::sqrt(kGravity * kLength);
    const T x = fn / p[kFnLift];
    const T x4 = x * x * x * x;
    return x4 / (T(1) + x4);
  }

  // Wetted area over wetted area at rest, lambda in (wetted_planing, 1].
  template <typename T>
  static T WettedFraction(const T& speed, const T* p) {
    return T(1) - (T(1) - p[kWettedPlaning]) * LiftShare(speed, p);
  }

  // Calm-water resistance [N] going ahead at speed U [m/s] (U > 0).
  template <typename T>
  static T Resistance(const T& speed, const T* p) {
    return ResistanceAt(speed, LiftShare(speed, p), p);
  }

  // Surge thrust of both jets [N] at shaft speed rpm, bucket b, nozzle delta, inlet speed u_r.
  template <typename T>
  static T SurgeThrust(const T& rpm, const T& u_r, const T& bucket, const T& nozzle, const T* p) {
    using std::cos;
    const T q = p[kJetFlowPerRpm] * rpm;
    const T v_jet = q / p[kNozzleArea];
    return T(2 * kRho) * q *
           (BucketGain(bucket, p) * v_jet * cos(nozzle) - (T(1) - p[kWakeFraction]) * u_r);
  }

  template <typename T>
  static void Derivative(const T* x, const T* in, const T* p, const Environment<T>& env, T* dx) {
    using std::cos;
    using std::sin;
    using std::sqrt;
    using std::tanh;
    const T &psi = x[2], &u = x[3], &v = x[4], &r = x[5];
    const T &rpm = x[6], &nozzle = x[7], &bucket = x[8];
    const T c = cos(psi);
    const T s = sin(psi);
    const T u_c = c * env.current_north + s * env.current_east;
    const T v_c = -s * env.current_north + c * env.current_east;
    const T u_r = u - u_c;
    const T v_r = v - v_c;

    // Regime: lift share, wetted fraction, side-force centre.
    const T speed = sqrt(u_r * u_r + v_r * v_r + T(kEps * kEps));
    const T ahead = T(0.5) + T(0.5) * tanh(u_r / T(kAheadSmoothing));
    const T f = LiftShare(speed, p) * ahead;
    const T lambda = T(1) - (T(1) - p[kWettedPlaning]) * f;
    const T x_p = p[kXLatDisp] + (p[kXLatPlan] - p[kXLatDisp]) * f;

    // Hull: resistance along the track projected on x, side force and yaw moment.
    const T v_p = v_r + x_p * r;
    const T lift = p[kYuv] * lambda * speed;
    const T k2 = lambda * lambda * T(kLength * kLength / 12.0);
    const T lambda2 = lambda * lambda;
    const T y_h = -lift * v_p - p[kYvv] * lambda * sqrt(v_p * v_p + T(kEps * kEps)) * v_p;
    T x_sum = -ResistanceAt(speed, f, p) * u_r / speed;
    T y_sum = y_h;
    T n_sum = x_p * y_h - (lift * k2 + p[kNr]) * r -
              p[kNrr] * lambda2 * lambda2 * sqrt(r * r + T(kEps * kEps)) * r;

    // Jets: momentum thrust, steering and inlet momentum, per jet at (kJetX, +-kJetY).
    const T q = p[kJetFlowPerRpm] * rpm;
    const T v_jet = q / p[kNozzleArea];
    const T fx = T(kRho) * q *
                 (BucketGain(bucket, p) * v_jet * cos(nozzle) - (T(1) - p[kWakeFraction]) * u_r);
    const T fy = -T(kRho) * q * (v_jet * sin(nozzle) + v_r + T(kJetX) * r);
    for (const double y_jet : {kJetY, -kJetY}) {
      x_sum += fx;
      y_sum += fy;
      n_sum += T(kJetX) * fy - T(y_jet) * fx;
    }

    // Rigid body + added mass (quasi-steady in lambda), Coriolis on relative velocities.
    const T m11 = p[kM] + p[kXud];
    const T lambda3 = lambda2 * lambda;
    const T m22 = p[kM] + p[kYvd] * lambda3;
    const T m33 = p[kIz] + p[kNrd] * lambda3;
    dx[0] = c * u - s * v;
    dx[1] = s * u + c * v;
    dx[2] = r;
    dx[3] = (m22 * v_r * r + x_sum) / m11 + r * v_c;
    dx[4] = (-m11 * u_r * r + y_sum) / m22 - r * u_c;
    dx[5] = (-(m22 - m11) * u_r * v_r + n_sum) / m33;

    // Actuators: slew-limited first-order responses to the (delayed) commands.
    const T rpm_cmd = T(kIdleRpm) + T(kMaxRpm - kIdleRpm) * in[0];
    dx[6] = SlewLimited(rpm_cmd - rpm, p[kRpmTau], p[kRpmRate]);
    dx[7] = SlewLimited(in[1] - nozzle, p[kNozzleTau], p[kNozzleRate]);
    dx[8] = SlewLimited(in[2] - bucket, p[kBucketTau], p[kBucketRate]);
  }

 private:
  // Resistance [N] at speed U with lift share f (f = 0 going astern: no planing lift).
  template <typename T>
  static T ResistanceAt(const T& speed, const T& f, const T* p) {
    using std::log10;
    const T lambda = T(1) - (T(1) - p[kWettedPlaning]) * f;
    const T reynolds = speed * lambda * kLength / kNu + kReynoldsFloor;
    const T log_re = log10(reynolds) - T(2);
    const T cf = T(0.075) / (log_re * log_re);
    const T friction = T(0.5 * kRho) * p[kS0] * lambda * speed * speed * p[kFormFactor] * cf;
    const T x = speed / (std::sqrt(kGravity * kLength) * p[kFnHump]);
    const T x6 = x * x * x * x * x * x;
    const T wave = T(2) * x6 / (T(1) + x6);
    return friction + (T(1) - f) * p[kRWave] * wave + f * p[kRPlan];
  }

  // Net jet momentum fraction along +x: b when ahead, astern_efficiency b when astern.
  template <typename T>
  static T BucketGain(const T& b, const T* p) {
    using std::tanh;
    const T& eta = p[kAsternEfficiency];
    return T(0.5) * b * ((T(1) + eta) + (T(1) - eta) * tanh(b / T(kBucketSmoothing)));
  }

  // y' for error e: e / tau near the set point, at most +-rate.
  template <typename T>
  static T SlewLimited(const T& error, const T& tau, const T& rate) {
    using std::tanh;
    return rate * tanh(error / (tau * rate));
  }
};

}  // namespace usvid
