#include "preprocessing/cubic_spline.h"

#include <algorithm>

#include "core/error.h"

namespace usvid {

CubicSpline::CubicSpline(std::vector<double> t, std::vector<double> y)
    : t_(std::move(t)), y_(std::move(y)), m_(t_.size(), 0.0) {
  const size_t n = t_.size();
  if (n < 2 || y_.size() != n) throw InputError("cubic spline: needs at least two points");
  for (size_t i = 1; i < n; ++i)
    if (!(t_[i] > t_[i - 1])) throw InputError("cubic spline: times must increase");
  if (n < 3) return;
  // Thomas algorithm on h_{i-1} m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_i m_{i+1} = rhs_i.
  std::vector<double> diag(n, 1.0), upper(n, 0.0), rhs(n, 0.0);
  for (size_t i = 1; i + 1 < n; ++i) {
    const double h0 = t_[i] - t_[i - 1], h1 = t_[i + 1] - t_[i];
    const double lower = h0;
    diag[i] = 2 * (h0 + h1);
    upper[i] = h1;
    rhs[i] = 6 * ((y_[i + 1] - y_[i]) / h1 - (y_[i] - y_[i - 1]) / h0);
    const double w = lower / diag[i - 1];
    diag[i] -= w * upper[i - 1];
    rhs[i] -= w * rhs[i - 1];
  }
  for (size_t i = n - 2; i >= 1; --i) m_[i] = (rhs[i] - upper[i] * m_[i + 1]) / diag[i];
}

double CubicSpline::operator()(double t) const {
  const size_t n = t_.size();
  const auto it = std::upper_bound(t_.begin(), t_.end(), t);
  const size_t i = std::clamp<size_t>(static_cast<size_t>(it - t_.begin()), 1, n - 1) - 1;
  const double h = t_[i + 1] - t_[i];
  const double a = (t_[i + 1] - t) / h, b = (t - t_[i]) / h;
  return a * y_[i] + b * y_[i + 1] +
         ((a * a * a - a) * m_[i] + (b * b * b - b) * m_[i + 1]) * h * h / 6.0;
}

}  // namespace usvid
