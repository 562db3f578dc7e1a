#include "metrics/criteria_smoothing.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "preprocessing/smoothing_spline.h"

namespace usvid {

Eigen::VectorXd SmoothedForCriteria(const Eigen::Ref<const Eigen::VectorXd>& t,
                                    const Eigen::Ref<const Eigen::VectorXd>& x) {
  constexpr Eigen::Index kMinSamples = 8;
  constexpr double kJitter = 0.05;
  const Eigen::Index n = x.size();
  if (n < kMinSamples || t.size() != n || !x.allFinite() || !t.allFinite()) return x;
  std::vector<double> dt(n - 1);
  for (Eigen::Index k = 1; k < n; ++k) dt[k - 1] = t(k) - t(k - 1);
  std::vector<double> sorted = dt;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  if (!(median > 0)) return x;
  for (double d : dt)
    if (std::abs(d - median) > kJitter * median) return x;
  // A replay that ran far out (finite, but past what the spline's sums hold) is read as it is.
  Eigen::VectorXd smoothed = SmoothingSpline(x, median).value;
  return smoothed.allFinite() ? smoothed : Eigen::VectorXd(x);
}

}  // namespace usvid
