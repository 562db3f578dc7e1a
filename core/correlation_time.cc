#include "core/correlation_time.h"

#include <algorithm>

namespace usvid {

double CorrelationTime(const Eigen::Ref<const Eigen::VectorXd>& residual, int channels) {
  if (channels < 1) return 1.0;
  const Eigen::Index n = residual.size() / channels;
  double total = 0.0;
  for (int c = 0; c < channels; ++c) {
    Eigen::VectorXd e(n);
    for (Eigen::Index k = 0; k < n; ++k) e(k) = residual(k * channels + c);
    e.array() -= e.mean();
    const double var = e.squaredNorm();
    double tau = 1.0;
    for (Eigen::Index lag = 1; lag < std::min<Eigen::Index>(n / 4, 400) && var > 0; ++lag) {
      const double rho = e.head(n - lag).dot(e.tail(n - lag)) / var;
      if (rho < 0.05) break;
      tau += 2.0 * rho;
    }
    total += tau;
  }
  return total / channels;
}

}  // namespace usvid
