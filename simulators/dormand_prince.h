// Adaptive Dormand-Prince 5(4) integration of x' = f(x) over [0, span] with error control,
// any scalar T (double, ceres::Jet). The embedded 4th-order solution estimates the local error;
// a step is accepted when max_i |err_i| / (atol + rtol max(|x_i|, |x_new_i|)) <= 1, and the
// next step is h * clamp(0.9 err^(-1/5), 0.2, 5). Step control looks at values only (ValueOf),
// so a Jet rollout takes exactly the steps of the double rollout. Inputs are constant over the
// span (zero-order hold): integrate each input interval separately.
#pragma once

#include <algorithm>
#include <cmath>

#include "simulators/rk4.h"
#include "simulators/scalar.h"

namespace usvid {

struct AdaptiveOptions {
  double rtol = 1e-8;
  double atol = 1e-10;
  double initial_step = 0.01;
  double min_step = 1e-9;
  int max_steps = 1000000;
};

struct AdaptiveResult {
  bool ok = true;  // false: step size fell below min_step or max_steps was reached
  int steps = 0;   // accepted steps
  int rejected = 0;
  double last_step = 0.0;  // a good first step for the next interval
};

template <typename T, int N, typename F>
AdaptiveResult DormandPrinceIntegrate(const F& f, double span, StateVector<T, N>& x,
                                      const AdaptiveOptions& opt = {}) {
  constexpr double a21 = 1.0 / 5, a31 = 3.0 / 40, a32 = 9.0 / 40, a41 = 44.0 / 45, a42 = -56.0 / 15,
                   a43 = 32.0 / 9, a51 = 19372.0 / 6561, a52 = -25360.0 / 2187,
                   a53 = 64448.0 / 6561, a54 = -212.0 / 729, a61 = 9017.0 / 3168, a62 = -355.0 / 33,
                   a63 = 46732.0 / 5247, a64 = 49.0 / 176, a65 = -5103.0 / 18656, b1 = 35.0 / 384,
                   b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
  // Error coefficients: 5th-order minus embedded 4th-order weights.
  constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                   e6 = 22.0 / 525, e7 = -1.0 / 40;
  AdaptiveResult result;
  double t = 0.0;
  double h = std::min(opt.initial_step, span);
  StateVector<T, N> k1, k2, k3, k4, k5, k6, k7, y, x_new;
  f(x.data(), k1.data());
  while (t < span) {
    if (result.steps + result.rejected >= opt.max_steps || h < opt.min_step) {
      result.ok = false;
      return result;
    }
    const bool last = t + h >= span * (1 - 1e-12);
    if (last) h = span - t;
    y = x + h * (a21 * k1);
    f(y.data(), k2.data());
    y = x + h * (a31 * k1 + a32 * k2);
    f(y.data(), k3.data());
    y = x + h * (a41 * k1 + a42 * k2 + a43 * k3);
    f(y.data(), k4.data());
    y = x + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4);
    f(y.data(), k5.data());
    y = x + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5);
    f(y.data(), k6.data());
    x_new = x + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
    f(x_new.data(), k7.data());
    double err = 0.0;
    for (int i = 0; i < N; ++i) {
      const double e = ValueOf(
          h * (e1 * k1(i) + e3 * k3(i) + e4 * k4(i) + e5 * k5(i) + e6 * k6(i) + e7 * k7(i)));
      const double scale =
          opt.atol + opt.rtol * std::max(std::abs(ValueOf(x(i))), std::abs(ValueOf(x_new(i))));
      err = std::max(err, std::abs(e) / scale);
    }
    if (!std::isfinite(err)) err = 1e10;
    const double factor = std::clamp(0.9 * std::pow(std::max(err, 1e-10), -0.2), 0.2, 5.0);
    if (err <= 1.0) {
      t = last ? span : t + h;
      x = x_new;
      k1 = k7;  // first-same-as-last
      ++result.steps;
      result.last_step = h;
    } else {
      ++result.rejected;
    }
    h *= factor;
  }
  return result;
}

}  // namespace usvid
