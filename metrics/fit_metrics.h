// How well a simulated channel follows the measured one (docs/data.md#metricsjson):
//   fit % = 100 (1 - ||y - y_hat|| / ||y - mean(y)||)   (MATLAB's compare; 100 is perfect,
//           0 is no better than the mean, negative is worse),
//   rmse  = ||y - y_hat|| / sqrt(n),   nrmse = rmse / std(y).
// Rows where either value is not finite are skipped; a channel with no variance (a standard
// deviation at most kNoVarianceRelative of max(1, |mean|)) gets fit 0 and nrmse 0.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace usvid {

inline constexpr double kNoVarianceRelative = 1e-9;

struct ChannelScore {
  double fit_percent = 0.0;
  double nrmse = 0.0;
  double rmse = 0.0;
  long samples = 0;

  nlohmann::json ToJson() const;
};

ChannelScore ScoreChannel(const Eigen::VectorXd& measured, const Eigen::VectorXd& simulated);

// 1 - SSR / SST of a prediction of a (derivative) signal.
double RSquared(const Eigen::VectorXd& target, const Eigen::VectorXd& prediction);

}  // namespace usvid
