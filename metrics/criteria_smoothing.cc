#include "metrics/criteria_smoothing.h"

#include <cmath>

#include "core/dataset.h"
#include "preprocessing/smoothing_spline.h"

namespace usvid {

Eigen::VectorXd SmoothedForCriteria(const Eigen::Ref<const Eigen::VectorXd>& t,
                                    const Eigen::Ref<const Eigen::VectorXd>& x) {
  constexpr Eigen::Index kMinSamples = 8;
  constexpr double kJitter = 0.05;
  const Eigen::Index n = x.size();
  if (n < kMinSamples || t.size() != n || !x.allFinite() || !t.allFinite()) return x;
  const double median = MedianInterval(t);
  if (!(median > 0)) return x;
  for (Eigen::Index k = 1; k < n; ++k)
    if (std::abs(t(k) - t(k - 1) - median) > kJitter * median) return x;
  // A replay that ran far out (finite, but past what the spline's sums hold) is read as it is.
  Eigen::VectorXd smoothed = SmoothingSpline(x, median).value;
  return smoothed.allFinite() ? smoothed : Eigen::VectorXd(x);
}

}  // namespace usvid
