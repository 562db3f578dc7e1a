#include "metrics/fit_metrics.h"

#include <algorithm>
#include <cmath>

namespace usvid {

nlohmann::json ChannelScore::ToJson() const {
  return {{"fit_percent", fit_percent}, {"nrmse", nrmse}, {"rmse", rmse}, {"samples", samples}};
}

ChannelScore ScoreChannel(const Eigen::VectorXd& measured, const Eigen::VectorXd& simulated) {
  ChannelScore s;
  double sum = 0.0;
  for (Eigen::Index i = 0; i < measured.size(); ++i)
    if (std::isfinite(measured(i)) && std::isfinite(simulated(i))) {
      sum += measured(i);
      ++s.samples;
    }
  if (s.samples == 0) return s;
  const double mean = sum / static_cast<double>(s.samples);
  double err2 = 0.0, var2 = 0.0;
  for (Eigen::Index i = 0; i < measured.size(); ++i)
    if (std::isfinite(measured(i)) && std::isfinite(simulated(i))) {
      err2 += std::pow(measured(i) - simulated(i), 2);
      var2 += std::pow(measured(i) - mean, 2);
    }
  const double n = static_cast<double>(s.samples);
  s.rmse = std::sqrt(err2 / n);
  // A spread at rounding level is no variance: a throttle's rpm held through a zig-zag varies by
  // 1e-12 of itself, and a model a little off its level would score -1e13 %.
  const bool varies = std::sqrt(var2 / n) > kNoVarianceRelative * std::max(1.0, std::abs(mean));
  s.nrmse = varies ? s.rmse / std::sqrt(var2 / n) : 0.0;
  s.fit_percent = varies ? 100.0 * (1.0 - std::sqrt(err2 / var2)) : 0.0;
  return s;
}

double RSquared(const Eigen::VectorXd& target, const Eigen::VectorXd& prediction) {
  const double sst = (target.array() - target.mean()).square().sum();
  const double ssr = (target - prediction).squaredNorm();
  return sst > 0 && std::isfinite(ssr) ? 1.0 - ssr / sst : 0.0;
}

}  // namespace usvid
