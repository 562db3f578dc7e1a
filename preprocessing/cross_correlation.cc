#include "preprocessing/cross_correlation.h"

#include <cmath>

namespace usvid {

LagEstimate EstimateLag(const Eigen::VectorXd& early, const Eigen::VectorXd& late, int max_lag) {
  const Eigen::Index n = std::min(early.size(), late.size());
  const Eigen::ArrayXd a = early.head(n).array() - early.head(n).mean();
  const Eigen::ArrayXd b = late.head(n).array() - late.head(n).mean();
  const double norm = std::sqrt(a.square().sum() * b.square().sum());
  auto corr = [&](int lag) {
    const Eigen::Index m = n - std::abs(lag);
    if (m <= 0 || norm == 0.0) return 0.0;
    // late(t) vs early(t - lag)
    return lag >= 0 ? (a.head(m) * b.tail(m)).sum() / norm : (a.tail(m) * b.head(m)).sum() / norm;
  };
  LagEstimate best{0.0, 0, corr(0)};
  for (int lag = -max_lag; lag <= max_lag; ++lag) {
    const double c = corr(lag);
    if (c > best.correlation) best = {static_cast<double>(lag), lag, c};
  }
  const double left = corr(best.integer_lag - 1), right = corr(best.integer_lag + 1);
  const double curvature = left - 2 * best.correlation + right;
  if (curvature < 0 && std::abs(best.integer_lag) < max_lag)
    best.lag = best.integer_lag + 0.5 * (left - right) / curvature;
  return best;
}

}  // namespace usvid
