#include "methods/sindy/weak_form.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/dataset.h"
#include "core/error.h"
#include "core/stretches.h"

namespace usvid::sindy {

WeakWindows MakeWeakWindows(const Eigen::VectorXd& t, Eigen::Index window_rows) {
  if (window_rows < 5)
    throw InputError("sindy: a weak-form window needs at least 5 rows, not " +
                     std::to_string(window_rows));
  if (window_rows % 2 == 0) ++window_rows;
  WeakWindows out;
  const double dt = t.size() < 2 ? 1.0 : MedianInterval(t);
  const Eigen::Index half = window_rows / 2;
  const double h = static_cast<double>(half) * dt;
  out.phi.resize(window_rows);
  out.dphi.resize(window_rows);
  for (Eigen::Index i = 0; i < window_rows; ++i) {
    const double s = static_cast<double>(i - half) / static_cast<double>(half);
    const double q = 1.0 - s * s;
    out.phi(i) = q * q * q * q * dt;
    out.dphi(i) = -8.0 * s * q * q * q / h * dt;
  }
  const double area = out.phi.sum();
  out.phi /= area;
  out.dphi /= area;
  for (const Stretch& s : Stretches(t, kGridGapFactor)) {
    const auto begin = static_cast<Eigen::Index>(out.windows.size());
    for (Eigen::Index first = s.first; first + window_rows <= s.end; first += half)
      out.windows.emplace_back(first, first + window_rows);
    const auto end = static_cast<Eigen::Index>(out.windows.size());
    if (end > begin) out.stretches.emplace_back(begin, end);
  }
  return out;
}

Eigen::Index WeakWindowRows(const Eigen::VectorXd& t, double seconds) {
  const double dt = t.size() < 2 ? 1.0 : MedianInterval(t);
  const Eigen::Index rows = std::max<Eigen::Index>(5, std::lround(seconds / dt) + 1);
  return rows % 2 == 0 ? rows + 1 : rows;
}

double LongestWeakWindow(const Eigen::VectorXd& t, double seconds, Eigen::Index min_windows) {
  const double dt = t.size() < 2 ? 1.0 : MedianInterval(t);
  for (Eigen::Index rows = WeakWindowRows(t, seconds); rows >= 5; rows -= 2)
    if (static_cast<Eigen::Index>(MakeWeakWindows(t, rows).windows.size()) >= min_windows)
      return static_cast<double>(rows - 1) * dt;
  return 0.0;
}

Eigen::MatrixXd WeakColumns(const WeakWindows& w, const Eigen::MatrixXd& columns) {
  Eigen::MatrixXd out(static_cast<Eigen::Index>(w.windows.size()), columns.cols());
  for (size_t k = 0; k < w.windows.size(); ++k) {
    const auto [first, end] = w.windows[k];
    out.row(static_cast<Eigen::Index>(k)) =
        w.phi.transpose() * columns.middleRows(first, end - first);
  }
  return out;
}

Eigen::VectorXd WeakTarget(const WeakWindows& w, const Eigen::VectorXd& x) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(w.windows.size()));
  for (size_t k = 0; k < w.windows.size(); ++k) {
    const auto [first, end] = w.windows[k];
    out(static_cast<Eigen::Index>(k)) = -w.dphi.dot(x.segment(first, end - first));
  }
  return out;
}

}  // namespace usvid::sindy
