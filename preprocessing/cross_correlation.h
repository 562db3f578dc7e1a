// The lag at which two equally sampled signals agree best: the peak of their normalised
// cross-correlation over lags -max_lag..max_lag, refined to a fraction of a sample by a parabola
// through the peak and its neighbours. A positive lag means `late` follows `early` by that many
// samples (late(t) ~ early(t - lag)).
#pragma once

#include <Eigen/Core>

namespace usvid {

struct LagEstimate {
  double lag = 0.0;          // samples, sub-sample refined
  int integer_lag = 0;       // samples, the peak itself
  double correlation = 0.0;  // normalised correlation at the peak, in [-1, 1]
};

LagEstimate EstimateLag(const Eigen::VectorXd& early, const Eigen::VectorXd& late, int max_lag);

}  // namespace usvid
