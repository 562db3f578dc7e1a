// The wind's force and moment on a ship's body above the water, from the relative (apparent)
// wind that an anemometer on board measures. The coefficients are Fujiwara, Ueno & Nimura's
// Fourier series in the angle of attack (1998, "Estimation of wind forces and moments acting on
// ships", J Soc Naval Archit Japan 183, 77-90):
//   C_X = X_0 + X_1 cos a + X_3 cos 3a + X_5 cos 5a
//   C_Y = Y_1 sin a + Y_3 sin 3a + Y_5 sin 5a
//   C_N = N_1 sin a + N_2 sin 2a + N_3 sin 3a
//   X_A = q A_T C_X,   Y_A = q A_L C_Y,   N_A = q A_L L C_N,   q = 1/2 rho_air V_A^2
// with V_A the relative wind speed [m/s] and a = -gamma_A, gamma_A the relative direction the
// wind blows from, clockwise from the bow [rad] (0: a head wind; pi/2: from starboard). Fujiwara
// counts the angle the other way round. X ahead, Y to starboard, N turning to starboard, about
// midship, as in the MMG model (simulators/mmg_forces.h). simulation/wind_estimates.h estimates
// the ten coefficients from the areas and heights of the body above water;
// docs/model.md#wind gives the channels and the formulas.
//
// The coefficients are the scalar T (a fit may free them); the areas are doubles.
#pragma once

#include <array>
#include <cmath>
#include <string_view>
#include <type_traits>

#include "simulators/scalar.h"

namespace usvid {

struct WindCoefficients {
  static constexpr int kCount = 10;
  static constexpr std::array<std::string_view, kCount> kNames = {
      "C_X0", "C_X1", "C_X3", "C_X5", "C_Y1", "C_Y3", "C_Y5", "C_N1", "C_N2", "C_N3"};
  enum Param { kX0, kX1, kX3, kX5, kY1, kY3, kY5, kN1, kN2, kN3 };
};

// The body above water, SI units.
struct WindAreas {
  double rho_air = 1.22;  // [kg/m^3]
  double A_T = 0.0;       // [m^2] transverse projected area
  double A_L = 0.0;       // [m^2] lateral projected area
  double L = 0.0;         // [m] the length the moment is made nondimensional with (L_pp)
};

// Adds `factor` times the wind's force and moment to f[0..2] (X, Y, N). c: the ten coefficients
// in WindCoefficients::kNames order. Nothing is added without areas or without wind.
template <typename T>
void AddWindForce(const T& speed, const T& direction, const T* c, const WindAreas& w,
                  const T& factor, T* f) {
  using std::cos;
  using std::sin;
  using C = WindCoefficients;
  if ((w.A_T == 0.0 && w.A_L == 0.0) || ValueOf(speed) == 0.0) return;
  if constexpr (std::is_same_v<T, double>)
    if (factor == 0.0) return;  // a Jet's factor may be 0 with a derivative
  const T a = -direction;
  const T cx = c[C::kX0] + c[C::kX1] * cos(a) + c[C::kX3] * cos(3.0 * a) + c[C::kX5] * cos(5.0 * a);
  const T cy = c[C::kY1] * sin(a) + c[C::kY3] * sin(3.0 * a) + c[C::kY5] * sin(5.0 * a);
  const T cn = c[C::kN1] * sin(a) + c[C::kN2] * sin(2.0 * a) + c[C::kN3] * sin(3.0 * a);
  const T q = factor * (0.5 * w.rho_air) * speed * speed;
  f[0] += q * w.A_T * cx;
  f[1] += q * w.A_L * cy;
  f[2] += q * w.A_L * w.L * cn;
}

}  // namespace usvid
