// The design's prediction checked by simulation: N seeded noisy runs of the maneuver, each
// fitted by the method (methods/identify), and the observed spread of each parameter beside the
// predicted sd (information.h). The ratio predicted / observed near 1 says the predicted
// covariance describes the method's estimates; far above 1, the estimates scatter less than
// predicted (a prior at work); far below, the fit has errors the prediction does not see (local
// minima, bias, for eb-lr steady windows that differ from run to run).
#pragma once

#include <string>
#include <vector>

#include "design/information.h"

namespace usvid::design {

struct SpreadCheck {
  int runs = 0, failed = 0;
  std::vector<double> observed_sd, mean, ratio;  // per parameter of the information
  double median_ratio = 0.0;
};

// Runs with seeds 1..runs, fitted in parallel on `threads` (each fit single-threaded: the same
// numbers at any thread count).
SpreadCheck CheckSpread(const DesignProblem& problem, const ManeuverInformation& predicted,
                        int runs, int threads);

}  // namespace usvid::design
