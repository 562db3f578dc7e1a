// The integrated autocorrelation time of residuals [samples]: per channel 1 + 2 sum rho_k over
// the lags before rho first drops below 0.05 (at most min(n / 4, 400) lags), averaged over the
// channels. N residuals carry about N / tau independent ones (the diagnosis's and the hybrid's
// likelihood ratios).
#pragma once

#include <Eigen/Core>

namespace usvid {

// `residual` holds rows of `channels` values, row-major (rows = size / channels).
double CorrelationTime(const Eigen::Ref<const Eigen::VectorXd>& residual, int channels);

}  // namespace usvid
