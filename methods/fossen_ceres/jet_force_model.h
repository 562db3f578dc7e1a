// The Fossen 3-DOF form for a high-speed waterjet craft (odin-hs, docs/vessels/odin-hs.md), on
// the jets' measured forces (`--forces waterjet`: inputs tau_x, tau_y [N], tau_n [N m] and the
// total jet flow jet_flow Q [m^3/s]), with damping that depends on speed as far as the data
// support it (issue 19). In calm water, nu = [u v r], U = sqrt(u^2 + v^2 + eps^2):
//
//   m11 u' = tau_x + Xvr v r - (XQ Q + c(U) U) u
//   m22 v' = tau_y - m11 u r - (Yv + YUv U + YQv Q) v - Yvv |v| v - (Yr + YUr U + YQr Q) r
//   m33 r' = tau_n - (m22 - m11) u v - (Nv + NUv U + NQv Q) v - (Nr + NUr U + NQr Q) r
//            - Nrr |r| r
//
// Why each term (the physics of docs/vessels/odin-hs.md, none of its constants):
//  - c(U) U u is the resistance R(U) = c(U) U^2 along the track. c(U) = R / U^2 is
//    piecewise-linear in U with knots every 0.5 m/s from 0 to 20 m/s (Froude-number steps of 0.05
//    for a 10.5 m hull) and held above 20 m/s: it can take the resistance hump and the fall of
//    R / U^2 when dynamic lift takes over, the change of regime, without being told its form.
//    2 m/s knots cut the hump's peak and cost 3 % of the resistance there (a zig-zag's surge fit
//    fell from 80 % to -63 %). A first-difference penalty (one residual per pair of knots, the
//    weight of one sample of tau_x) keeps knots without data at their neighbours' value: beyond
//    the data, resistance grows as U^2 (a P-spline prior, Eilers and Marx 1996).
//  - XQ Q u, YQv Q v, YQr Q r, NQv Q v, NQr Q r are the inlet momentum: the jets take water in at
//    the boat's velocity, a drag in proportion to the flow (-rho Q (u, v + x_j r) at the inlet).
//  - The side-force slope of a planing hull grows with speed (lift ~ U), so the linear sway and
//    yaw damping have a part in proportion to U.
//  - The added masses shrink with the wetted area as the hull rises, so the surge coupling Xvr
//    (m22 v r at rest) has its own coefficient; the rest of that change is folded into damping.
// m11 is free: the forces are measured in newtons, so nothing is scaled away.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <string_view>

#include "core/parse_number.h"
#include "methods/fossen_ceres/fossen_models.h"
#include "simulators/scalar.h"

namespace usvid::fossen {

struct JetForceModel : FossenModelBase<JetForceModel> {
  static constexpr std::string_view kName = "fossen-jet";
  static constexpr int kInputs = 4, kYawInput = 2;
  static constexpr int kKnots = 41;            // c(U) at U = 0, 0.5, ..., 20 m/s
  static constexpr double kKnotSpacing = 0.5;  // [m/s]
  static constexpr int kFirstKnot = 19;        // the parameter of c(0)
  static constexpr int kParams = kFirstKnot + kKnots;
  static constexpr int kPenaltyResiduals = kKnots - 1;
  static constexpr bool kAccelerationResidual = false;  // tau is measured: residual in forces
  static constexpr bool kLinearEquationError = true;    // and linear in the parameters
  // The shooting fit stops when a step changes the cost by less than 1e-8 of it: on a 25 min step
  // grid, 69 steps instead of 87 (54 s instead of 65 s) and the same cost to 0.5 %; 1e-6 stopped
  // at twice the cost.
  static constexpr double kFunctionTolerance = 1e-8;
  static constexpr int kFixedParam = -1;
  static constexpr double kSpeedEps = 1e-3;  // [m/s] keeps U differentiable at rest
  static constexpr std::array<std::string_view, kInputs> kInputNames = {"tau_x", "tau_y", "tau_n",
                                                                        "jet_flow"};
  static constexpr std::array<std::string_view, kParams> kParamNames = {
      "m11",   "m22", "m33",   "XQ",  "Yv",    "YUv", "Yvv",   "Yr",  "YUr",   "YQv",
      "YQr",   "Nv",  "NUv",   "Nr",  "NUr",   "Nrr", "NQv",   "NQr", "Xvr",   "c0",
      "c0_5",  "c1",  "c1_5",  "c2",  "c2_5",  "c3",  "c3_5",  "c4",  "c4_5",  "c5",
      "c5_5",  "c6",  "c6_5",  "c7",  "c7_5",  "c8",  "c8_5",  "c9",  "c9_5",  "c10",
      "c10_5", "c11", "c11_5", "c12", "c12_5", "c13", "c13_5", "c14", "c14_5", "c15",
      "c15_5", "c16", "c16_5", "c17", "c17_5", "c18", "c18_5", "c19", "c19_5", "c20"};
  // Parameter indices, in kParamNames order, up to the resistance knots (kFirstKnot on).
  enum Param {
    kM11, kM22, kM33, kXQ, kYv, kYUv, kYvv, kYr, kYUr, kYQv,
    kYQr, kNv, kNUv, kNr, kNUr, kNrr, kNQv, kNQr, kXvr};
  static_assert(kXvr + 1 == kFirstKnot);
  // The equation-error fit is linear in the parameters, so any start converges; these are of the
  // right order for a 5 t boat.
  static constexpr std::array<double, kParams> kStart = [] {
    std::array<double, kParams> p{5000, 5000, 20000, 500,  500,  500, 1000, 0, 0,   500,
                                  0,    0,    0,     3000, 3000, 1e4, 0,    0, 5000};
    for (int k = 0; k < kKnots; ++k) p[kFirstKnot + k] = 50.0;  // R / U^2 [kg/m]
    return p;
  }();
  static constexpr std::array<double, kParams> kDefaultParams = kStart;
  static constexpr std::array<ParamGroup, kParams> kParamGroups = [] {
    std::array<ParamGroup, kParams> g{};
    g.fill(ParamGroup::kDamping);
    g[kM11] = g[kM22] = g[kM33] = ParamGroup::kInertia;
    return g;
  }();
  static constexpr std::array<double, kInputs> kInputMin = {-3e4, -3e4, -1.2e5, 0.0};
  static constexpr std::array<double, kInputs> kInputMax = {3e4, 3e4, 1.2e5, 1.0};

  // Cross-coupling and inlet terms whose sign the physics does not fix.
  static constexpr bool Signed(int i) {
    return i == kYr || i == kYUr || i == kYQr || i == kNv || i == kNUv || i == kNQv || i == kNQr ||
           i == kXvr;
  }

  // The inertias are at least a tenth of a 5 t boat's: a record at one throttle (a zig-zag) lets
  // the equation error trade inertia for damping down to no mass at all.
  static constexpr double MinValue(int i) { return i <= kM33 ? 0.1 * kStart[i] : 0.0; }

  // c(U): the piecewise-linear resistance coefficient [kg/m] through the knots, held at the last
  // knot's value above it. Only the two hats around U are non-zero, so only they are evaluated.
  template <typename T>
  static T Resistance(const T* p, const T& speed) {
    const int j = KnotAt(ValueOf(speed));
    if (j == kKnots - 1) return p[kFirstKnot + j];
    const T w = speed / kKnotSpacing - double(j);
    return p[kFirstKnot + j] * (1.0 - w) + p[kFirstKnot + j + 1] * w;
  }

  // The first of the two knots c(U) reads at a speed (the last knot, alone, at and above it).
  static int KnotAt(double speed) {
    const double x = speed / kKnotSpacing;
    if (!(x < kKnots - 1)) return kKnots - 1;
    return std::clamp(static_cast<int>(std::floor(x)), 0, kKnots - 2);
  }
  // ... at the hull's velocity through the water (u, v), as Hull computes its speed.
  static int KnotAt(double u, double v) {
    return KnotAt(std::sqrt(u * u + v * v + kSpeedEps * kSpeedEps));
  }
  // ... in the state x, as Derivative computes the hull's velocity.
  static int KnotAt(const double* x, const Environment<double>& env) {
    const double c = std::cos(x[2]), s = std::sin(x[2]);
    const auto [ur, vr] = Relative(x, c, s, env);
    return KnotAt(ur, vr);
  }

  // The velocity the hull sees in a constant current (Fossen 2011, section 10.3); c, s the
  // cosine and sine of the heading.
  template <typename T>
  static std::array<T, 2> Relative(const T* x, const T& c, const T& s, const Environment<T>& env) {
    return {x[3] - (c * env.current_north + s * env.current_east),
            x[4] - (-s * env.current_north + c * env.current_east)};
  }

  // The forces are measured: tau_i = in[i].
  template <typename T>
  static void Forces(const T* /*p*/, const T* in, T* tau) {
    for (int i = 0; i < 3; ++i) tau[i] = in[i];
  }

  template <typename T>
  static void Hull(const T* p, const T& u, const T& v, const T& r, const T* in, T* h) {
    using std::abs;
    using std::sqrt;
    const T speed = sqrt(u * u + v * v + kSpeedEps * kSpeedEps);
    const T& q = in[3];
    h[0] = -p[kXvr] * v * r + (p[kXQ] * q + Resistance(p, speed) * speed) * u;
    h[1] = p[kM11] * u * r + (p[kYv] + p[kYUv] * speed + p[kYQv] * q) * v + p[kYvv] * abs(v) * v +
           (p[kYr] + p[kYUr] * speed + p[kYQr] * q) * r;
    h[2] = (p[kM22] - p[kM11]) * u * v + (p[kNv] + p[kNUv] * speed + p[kNQv] * q) * v +
           (p[kNr] + p[kNUr] * speed + p[kNQr] * q) * r + p[kNrr] * abs(r) * r;
  }

  template <typename T>
  static void Derivative(const T* x, const T* in, const T* p, const Environment<T>& env, T* dx) {
    using std::cos;
    using std::sin;
    const T c = cos(x[2]), s = sin(x[2]);
    const auto [ur, vr] = Relative(x, c, s, env);
    T tau[3], h[3];
    Forces(p, in, tau);
    Hull(p, ur, vr, x[5], in, h);
    dx[0] = c * x[3] - s * x[4];
    dx[1] = s * x[3] + c * x[4];
    dx[2] = x[5];
    for (int i = 0; i < 3; ++i) dx[3 + i] = (tau[i] - h[i]) / p[i];
  }

  // First differences of c(U) over the knots, in newtons at each knot's speed: where the data
  // say nothing, c(U) stays at its neighbours' value (resistance ~ U^2 beyond the data).
  template <typename T>
  static void Penalty(const T* p, T* res) {
    for (int k = 0; k + 1 < kKnots; ++k) {
      const double speed = kKnotSpacing * (k + 1);
      res[k] = (p[kFirstKnot + k + 1] - p[kFirstKnot + k]) * speed * speed;
    }
  }

  // The equations in channel names (docs/data.md#modeljson): the same arithmetic as Hull.
  static std::string EquationText(int i, const double* p) {
    auto n = [](double x) { return "(" + FormatNumber(x) + ")"; };
    const std::string speed = "sqrt(u*u + v*v + " + FormatNumber(kSpeedEps * kSpeedEps) + ")";
    // Hat k: (|U - x_k + h| - 2 |U - x_k| + |U - x_k - h|) / 2h; the last one rises to 1 and stays.
    std::string c;
    const double h = kKnotSpacing;
    for (int k = 0; k < kKnots; ++k) {
      const double x = h * k;
      auto dist = [&](double knot) { return "abs(" + speed + " - " + n(knot) + ")"; };
      c += (k ? " + " : "") + n(p[kFirstKnot + k]) + "*(" +
           (k + 1 < kKnots ? dist(x - h) + " - 2*" + dist(x) + " + " + dist(x + h)
                           : dist(x - h) + " - " + dist(x) + " + " + FormatNumber(h)) +
           ")/" + FormatNumber(2.0 * h);
    }
    if (i == 0)
      return "(tau_x + " + n(p[kXvr]) + "*v*r - (" + n(p[kXQ]) + "*jet_flow + (" + c + ")*" + speed +
             ")*u) / " + n(p[kM11]);
    if (i == 1)
      return "(tau_y - " + n(p[kM11]) + "*u*r - (" + n(p[kYv]) + " + " + n(p[kYUv]) + "*" + speed + " + " +
             n(p[kYQv]) + "*jet_flow)*v - " + n(p[kYvv]) + "*abs(v)*v - (" + n(p[kYr]) + " + " + n(p[kYUr]) +
             "*" + speed + " + " + n(p[kYQr]) + "*jet_flow)*r) / " + n(p[kM22]);
    return "(tau_n - (" + n(p[kM22]) + " - " + n(p[kM11]) + ")*u*v - (" + n(p[kNv]) + " + " + n(p[kNUv]) +
           "*" + speed + " + " + n(p[kNQv]) + "*jet_flow)*v - (" + n(p[kNr]) + " + " + n(p[kNUr]) + "*" +
           speed + " + " + n(p[kNQr]) + "*jet_flow)*r - " + n(p[kNrr]) + "*abs(r)*r) / " + n(p[kM33]);
  }
};

}  // namespace usvid::fossen
