// A vessel of the MMG standard form whose particulars and coefficients come from a file, not
// from the code: vessel type `mmg` (simulation/vessel_file.h reads the file; docs/model.md#
// vessel-files gives its keys and how missing coefficients are estimated). The equations are
// those of simulators/mmg_forces.h, the same code as the compiled-in kvlcc2's, so a kvlcc2
// written as a file runs the same to the last bits (tests/simulation/vessel_file_test.cc).
//
// States  north, east [m], psi [rad], u, v [m/s] (surge, and sway at midship), r [rad/s].
// Inputs  delta [rad] (rudder angle; delta_sign = +1: positive turns to starboard, the MMG sign;
//         -1: positive turns to port, ITTC), n [1/s] (propeller revolutions per second); then
//         the measured relative wind, not commands: wind_speed [m/s] and wind_direction [rad],
//         where it blows from, clockwise from the bow (simulators/wind_force.h). A record
//         without them has no wind.
// Wind    Fujiwara et al. 1998's force and moment (simulators/wind_force.h) times wind_factor
//         (1: the model has the wind, 0: it ignores it) plus the environment's wind_scale (the
//         effect `wind`). Without areas (A_T = A_L = 0) the vessel feels no wind.
// Propeller  four quadrants: turning ahead, K_T = k_0 + k_1 J_P + k_2 J_P^2 (mmg_forces.h) also
//         when the ship goes astern (J_P < 0); turning astern (n < 0), the effective coefficient
//         K_T = max(K_Ta_0 + K_Ta_1 J_s, K_Ta_min) with J_s = u / (n D_P) and no thrust deduction
//         (the surge model of the Esso Osaka MMG simulator, Miyauchi et al. 2022, J Mar Sci
//         Technol 27:1065-1083; docs/model.md#vessel-files).
// Parameters  the 37 MMG coefficients (MmgCoefficients::kNames), the three astern thrust
//         coefficients, the ten wind coefficients (WindCoefficients::kNames), then the
//         particulars (MmgParticulars, delta_sign, the air's density, the wind areas and
//         wind_factor), which are fixed: a fit may not free them, and no derivative flows
//         through them.
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "simulators/kvlcc2.h"
#include "simulators/mmg_forces.h"
#include "simulators/vessel.h"
#include "simulators/wind_force.h"

namespace usvid {

struct Mmg : MmgCoefficients {
  static constexpr std::string_view kName = "mmg";
  static constexpr int kAsternCount = 3, kWindCount = WindCoefficients::kCount,
                       kParticularCount = 16;
  static constexpr int kStates = 6, kInputs = 4, kCommandedInputs = 2,
                       kParams =
                           MmgCoefficients::kCount + kAsternCount + kWindCount + kParticularCount;
  static constexpr std::array<std::string_view, kStates> kStateNames = {"north", "east", "psi",
                                                                        "u",     "v",    "r"};
  static constexpr std::array<std::string_view, kInputs> kInputNames = {"delta", "n", "wind_speed",
                                                                        "wind_direction"};
  // KVLCC2's, as the defaults below; a vessel file sets its own limits, neutral inputs and
  // steering rate (VesselInfo::actuation). The wind's direction may be counted either way
  // round the compass.
  static constexpr std::array<double, kInputs> kInputMin = {-0.6109, 0.0, 0.0, -6.2832};
  static constexpr std::array<double, kInputs> kInputMax = {0.6109, 2.5, 100.0, 6.2832};
  static constexpr int kYawInput = 0, kThrustInput = 1, kRateState = 5, kHeadingState = 2;
  // What refit frees by default (docs/model.md#what-refit-frees): the resistance and the linear
  // hull terms, the two cubic yaw terms that decide a tight turn, and the wind's three leading
  // coefficients (a head wind's drag, the beam wind's force and the moment that turns the bow
  // into the wind; held by the prior where the record has no wind).
  static constexpr std::array<std::string_view, 10> kRefitParams = {
      "R_0", "Y_v", "Y_r", "N_v", "N_r", "N_vvr", "N_rrr", "C_X1", "C_Y1", "C_N2"};
  static constexpr bool kSpeedScaledForces = true;  // MMG: forces 1/2 rho L d U^2 X'(v', r')
  static constexpr double kRunInS = 7200.0;         // [s] at most, from rest to steady speed
  // Parameters from this index on are the particulars: fixed.
  static constexpr int kFixedFrom = MmgCoefficients::kCount + kAsternCount + kWindCount;

  enum Astern { kKTa0 = MmgCoefficients::kCount, kKTa1, kKTaMin };
  static constexpr int kWind = kKTaMin + 1;  // the first wind coefficient
  enum Particular {
    kRho = kFixedFrom,
    kLength,
    kDraft,
    kXG,
    kPropellerDiameter,
    kRudderArea,
    kRudderSpan,
    kXPropeller,
    kXRudder,
    kKappa,
    kFAlpha,
    kDeltaSign,
    kRhoAir,
    kAT,
    kAL,
    kWindFactor
  };

  static constexpr std::array<std::string_view, kParams> kParamNames = [] {
    std::array<std::string_view, kParams> n{};
    for (int i = 0; i < MmgCoefficients::kCount; ++i) n[i] = MmgCoefficients::kNames[i];
    n[kKTa0] = "K_Ta_0";
    n[kKTa1] = "K_Ta_1";
    n[kKTaMin] = "K_Ta_min";
    for (int i = 0; i < kWindCount; ++i) n[kWind + i] = WindCoefficients::kNames[i];
    constexpr std::array<std::string_view, kParticularCount> particulars = {
        "rho", "L",     "d",       "x_G",        "D_P",     "A_R", "H_R", "x_P",
        "x_R", "kappa", "f_alpha", "delta_sign", "rho_air", "A_T", "A_L", "wind_factor"};
    for (int i = 0; i < kParticularCount; ++i) n[kFixedFrom + i] = particulars[i];
    return n;
  }();
  // KVLCC2's, in this layout (simulators/kvlcc2.h): a vessel file replaces every one of them.
  static constexpr std::array<double, kParams> kDefaultParams = [] {
    std::array<double, kParams> p{};
    for (int i = 0; i < MmgCoefficients::kCount; ++i) p[i] = Kvlcc2::kDefaultParams[i];
    // kvlcc2 turns ahead only; these are Esso Osaka's (Miyauchi et al. 2022).
    p[kKTa0] = -0.175;
    p[kKTa1] = 0.33;
    p[kKTaMin] = -0.251;
    p[kRho] = Kvlcc2::kRho;
    p[kLength] = Kvlcc2::kLength;
    p[kDraft] = Kvlcc2::kDraft;
    p[kXG] = Kvlcc2::kXG;
    p[kPropellerDiameter] = Kvlcc2::kPropellerDiameter;
    p[kRudderArea] = Kvlcc2::kRudderArea;
    p[kRudderSpan] = Kvlcc2::kRudderSpan;
    p[kXPropeller] = Kvlcc2::kXPropeller;
    p[kXRudder] = Kvlcc2::kXRudder;
    p[kKappa] = Kvlcc2::kKappa;
    p[kFAlpha] = Kvlcc2::kFAlpha;
    p[kDeltaSign] = -1.0;
    // No body above the water: no wind (the coefficients stay 0 until a file gives areas).
    p[kRhoAir] = 1.22;
    p[kWindFactor] = 1.0;
    return p;
  }();
  static constexpr std::array<ParamGroup, kParams> kParamGroups = [] {
    std::array<ParamGroup, kParams> g{};
    for (int i = 0; i < kParams; ++i)
      g[i] = i < MmgCoefficients::kCount ? MmgCoefficients::Group(i) : ParamGroup::kOther;
    return g;
  }();

  template <typename T>
  static MmgParticulars Particulars(const T* p) {
    return {ValueOf(p[kRho]),
            ValueOf(p[kLength]),
            ValueOf(p[kDraft]),
            ValueOf(p[kXG]),
            ValueOf(p[kPropellerDiameter]),
            ValueOf(p[kRudderArea]),
            ValueOf(p[kRudderSpan]),
            ValueOf(p[kXPropeller]),
            ValueOf(p[kXRudder]),
            ValueOf(p[kKappa]),
            ValueOf(p[kFAlpha])};
  }

  // K_T in four quadrants (above).
  template <typename T>
  struct Thrust {
    const T* p;
    T operator()(const T& J, const T& J_s, const T& n) const {
      if (ValueOf(n) >= 0) return MmgForwardThrust<T>{p}(J, J_s, n);
      const T k = p[kKTa0] + p[kKTa1] * J_s;
      return ValueOf(k) > ValueOf(p[kKTaMin]) ? k : p[kKTaMin];
    }
  };

  template <typename T>
  static void Derivative(const T* x, const T* in, const T* p, const Environment<T>& env, T* dx) {
    const MmgParticulars s = Particulars(p);
    const WindAreas w{ValueOf(p[kRhoAir]), ValueOf(p[kAT]), ValueOf(p[kAL]), s.L};
    const T factor = T(ValueOf(p[kWindFactor])) + env.wind_scale;
    auto wind = [&](T* f) { AddWindForce(in[2], in[3], p + kWind, w, factor, f); };
    MmgMotion(x, T(ValueOf(p[kDeltaSign]) * in[0]), T(in[1]), p, s, env, Thrust<T>{p}, wind, dx);
  }
};

}  // namespace usvid
