// What the nominal simulation gets wrong, channel by channel, as numbers a person can read. With
// the residual e = measured - model (of the plain segment-reset run, each segment from the
// smoothed measurement, unless stated):
//   bias           mean of e [channel units]
//   drift_per_s    mean least-squares slope of e within the segments [units/s] (a current
//                  makes positions drift; a gyro bias makes r offset, not drift)
//   lag_s          how late the measured channel follows the model: the peak of their
//                  cross-correlation within +-5 s (delay, actuator lag, inertia show here)
//   inputs         per input, the peak correlation of e with the input level within +-5 s and
//                  its lag (positive: e follows the input)
//   regressors     correlation of e with cos psi, sin psi (heading-fixed causes such as a
//                  current), the speed, each input and |yaw input|
// and the fit % of the free run (no resets) and of the segment-reset run over all rows.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "diagnosis/measured_data.h"

namespace usvid::diagnosis {

struct InputCorrelation {
  std::string input;
  double lag_s = 0.0;
  double correlation = 0.0;
};

struct ChannelResidual {
  std::string channel;
  double free_run_fit_percent = 0.0;
  double segment_fit_percent = 0.0;
  double bias = 0.0;
  double drift_per_s = 0.0;
  double lag_s = 0.0;
  std::vector<InputCorrelation> inputs;
  std::map<std::string, double> regressors;
};

// residual: ResidualCount(data, data.all) values of the nominal model (reset_rollout.h);
// free_run: the nominal free run's states over all rows (rows may be fewer if it diverged).
std::vector<ChannelResidual> AnalyseResiduals(const MeasuredData& data,
                                              const Eigen::VectorXd& residual,
                                              const std::vector<std::string>& input_names,
                                              const Eigen::MatrixXd& free_run);

// Fit % of each channel over a part from its residuals: 100 (1 - ||e|| / ||y - mean y||).
std::map<std::string, double> FitPercentOf(const MeasuredData& data, const Part& part,
                                           const Eigen::VectorXd& residual);

// Mean squared normalised residual over the sampled entries of a part.
double MeanSquaredError(const MeasuredData& data, const Part& part,
                        const Eigen::VectorXd& residual);

}  // namespace usvid::diagnosis
