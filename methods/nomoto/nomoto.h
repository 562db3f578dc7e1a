// `nomoto`: the first-order Nomoto heading model of a ship or boat,
//    T r' + r = K (delta - delta0),     psi' = r,
// with K the gain [1/s per unit of the yaw input], T the time constant [s] and delta0 the
// neutral rudder (or yaw-input) offset: a step in delta brings r to K (delta - delta0) with time
// constant T. Identified in two steps from preprocessed data (rate r smoothed, "r_dot" its
// derivative, the yaw input shifted by the delay):
//  1. equation error: linear least squares of r' = a r + b delta + c, so that
//     T = -1/a, K = -b/a, delta0 = -c/b (a >= 0 is an unstable fit: T is clamped to a large
//     value, K = b T keeps the initial slope, and a note says so);
//  2. output error: Ceres Levenberg-Marquardt on the simulation error of r, by multiple
//     shooting over segments of segment_s seconds, each starting from its own free r (started
//     at the smoothed r of its first row) and rolled out by RK4 with the yaw input held over
//     each sample interval (substeps of at most 0.1 s). Residuals are (r_sim - r_measured) /
//     sd(r_measured), r_measured being "r_raw" when present, else r. Standard deviations come
//     from ceres::Covariance, scaled by the residual variance per degree of freedom.
#pragma once

#include <string_view>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "preprocessing/pipeline.h"

namespace usvid::nomoto {

// The name --method and suites give it (methods/method_list.h registers it).
inline constexpr std::string_view kMethodName = "nomoto";

struct NomotoFit {
  double K = 0.0, T = 0.0, delta0 = 0.0;           // output-error estimate
  double sd_K = 0.0, sd_T = 0.0, sd_delta0 = 0.0;  // 0 when the covariance is not available
  bool converged = false;
  std::string termination;  // Ceres' termination type and message
  double equation_error_K = 0.0, equation_error_T = 0.0, equation_error_delta0 = 0.0;
  std::vector<std::string> notes;
  double seconds = 0.0;  // both steps
};

// prepared: from Preprocess with state `rate` and input `yaw_input`. Throws InputError for a
// missing channel ("<rate>", "<rate>_dot", the input), a constant input, too few rows or a
// segment length that is not positive.
NomotoFit FitNomoto(const PreparedData& prepared, const std::string& rate,
                    const std::string& yaw_input, double segment_s = 30.0);

// {rate: "(K*(input - delta0) - rate)/T"} with the fitted numbers, in core/expression.h's
// syntax.
nlohmann::json NomotoEquations(const NomotoFit& fit, const std::string& rate,
                               const std::string& yaw_input);

}  // namespace usvid::nomoto
