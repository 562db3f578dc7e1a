#include "core/time_repair.h"

#include <cmath>
#include <sstream>

namespace usvid {
namespace {

void CountDisorder(const Eigen::VectorXd& t, TimeRepairReport& r) {
  r.rows_in = static_cast<int>(t.size());
  for (Eigen::Index i = 1; i < t.size(); ++i) {
    if (t(i) == t(i - 1)) ++r.repeated;
    if (t(i) < t(i - 1)) ++r.went_back;
  }
}

// The rounding step of a value printed with `digits` significant digits.
double RoundingStep(double value, int digits) {
  if (value == 0.0) return 0.0;
  return std::pow(10.0, std::floor(std::log10(std::abs(value))) - (digits - 1));
}

}  // namespace

std::string TimeRepairReport::Summary() const {
  std::ostringstream s;
  s << "time: " << rows_in << " rows, " << repeated << " repeated and " << went_back
    << " decreasing stamps";
  if (rebuilt)
    s << "; repaired " << repeated + went_back
      << " rows by rebuilding a uniform time base (dt = " << dt << " s, largest shift " << max_shift
      << " s)";
  if (dropped > 0) s << "; repaired by dropping " << dropped << " rows";
  if (!Changed()) s << "; nothing to repair";
  return s.str();
}

TimeRepairReport DropNonIncreasingRows(Dataset& data) {
  TimeRepairReport r;
  CountDisorder(data.t(), r);
  std::vector<bool> keep(data.rows(), true);
  double last = -INFINITY;
  for (Eigen::Index i = 0; i < data.rows(); ++i) {
    if (data.t()(i) <= last) {
      keep[i] = false;
      ++r.dropped;
    } else {
      last = data.t()(i);
    }
  }
  if (r.dropped > 0) data.KeepRows(keep);
  return r;
}

TimeRepairReport RebuildRoundedTime(Dataset& data, int significant_digits) {
  TimeRepairReport r;
  const Eigen::VectorXd& t = data.t();
  CountDisorder(t, r);
  const Eigen::Index n = t.size();
  if (n < 3 || (r.repeated == 0 && r.went_back == 0)) return r;

  // The grid starts at the first stamp: t_i = t_0 + i dt, dt by least squares weighted by the
  // inverse square of each stamp's rounding step (early stamps carry more digits).
  const Eigen::ArrayXd index = Eigen::ArrayXd::LinSpaced(n, 0.0, static_cast<double>(n - 1));
  Eigen::ArrayXd weight(n);
  for (Eigen::Index i = 0; i < n; ++i)
    weight(i) = 1.0 / std::pow(std::max(RoundingStep(t(i), significant_digits), 1e-9), 2);
  const double dt = (weight * index * (t.array() - t(0))).sum() / (weight * index.square()).sum();
  const Eigen::VectorXd grid = (t(0) + index * dt).matrix();
  bool consistent = dt > 0.0;
  double max_shift = 0.0;
  for (Eigen::Index i = 0; i < n && consistent; ++i) {
    const double shift = std::abs(grid(i) - t(i));
    max_shift = std::max(max_shift, shift);
    consistent = shift <= std::max(RoundingStep(t(i), significant_digits), dt);
  }
  if (!consistent) {
    TimeRepairReport dropped = DropNonIncreasingRows(data);
    return dropped;
  }
  data.SetTime(grid);
  r.rebuilt = true;
  r.dt = dt;
  r.max_shift = max_shift;
  return r;
}

}  // namespace usvid
