// Natural cubic spline interpolation through (t_i, y_i), t strictly increasing: piecewise cubic,
// twice continuously differentiable, second derivative zero at both ends. Built in O(n) by the
// tridiagonal system for the knot second derivatives; evaluated in O(log n).
// Throws InputError with fewer than two points or non-increasing t.
#pragma once

#include <vector>

namespace usvid {

class CubicSpline {
 public:
  CubicSpline(std::vector<double> t, std::vector<double> y);
  double operator()(double t) const;

 private:
  std::vector<double> t_, y_, m_;  // m_: second derivatives at the knots
};

}  // namespace usvid
