// Test signals with their exact derivatives, for the derivative estimators' tests.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace usvid::testing {

struct Signal {
  Eigen::VectorXd x, dx;  // samples and their true derivative
};

// Three sines (0.7, 1.9, 3.1 rad/s), n samples every dt seconds.
inline Signal Sines(int n, double dt) {
  Signal s{Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (int i = 0; i < n; ++i) {
    const double t = i * dt;
    s.x(i) = std::sin(0.7 * t) + 0.5 * std::sin(1.9 * t + 1.0) + 0.3 * std::sin(3.1 * t + 2.0);
    s.dx(i) =
        0.7 * std::cos(0.7 * t) + 0.95 * std::cos(1.9 * t + 1.0) + 0.93 * std::cos(3.1 * t + 2.0);
  }
  return s;
}

}  // namespace usvid::testing
