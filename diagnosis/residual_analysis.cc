#include "diagnosis/residual_analysis.h"

#include <cmath>

#include "diagnosis/reset_rollout.h"
#include "metrics/fit_metrics.h"
#include "preprocessing/cross_correlation.h"

namespace usvid::diagnosis {
namespace {

constexpr double kMaxLagS = 5.0;

double Correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const Eigen::ArrayXd x = a.array() - a.mean(), y = b.array() - b.mean();
  const double den = std::sqrt(x.square().sum() * y.square().sum());
  return den > 0 ? (x * y).sum() / den : 0.0;
}

// Rows of part `all` where channel c is sampled.
std::vector<Eigen::Index> SampledRows(const MeasuredData& d, int c) {
  std::vector<Eigen::Index> rows;
  for (Eigen::Index k = 0; k < d.rows(); ++k)
    if (d.sampled(k, c)) rows.push_back(k);
  return rows;
}

Eigen::VectorXd Gather(const Eigen::VectorXd& v, const std::vector<Eigen::Index>& rows) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(rows.size()));
  for (size_t i = 0; i < rows.size(); ++i) out(static_cast<Eigen::Index>(i)) = v(rows[i]);
  return out;
}

}  // namespace

std::map<std::string, double> FitPercentOf(const MeasuredData& d, const Part& part,
                                           const Eigen::VectorXd& residual) {
  std::map<std::string, double> fit;
  const auto channels = static_cast<Eigen::Index>(d.channels.size());
  for (Eigen::Index c = 0; c < channels; ++c) {
    std::vector<double> y, e;
    for (Eigen::Index k = part.begin; k < part.end; ++k) {
      if (!d.sampled(k, c)) continue;
      y.push_back(d.measured(k, c));
      e.push_back(residual((k - part.begin) * channels + c) * d.scale[c]);
    }
    const Eigen::Map<const Eigen::VectorXd> ym(y.data(), static_cast<Eigen::Index>(y.size()));
    const Eigen::Map<const Eigen::VectorXd> em(e.data(), static_cast<Eigen::Index>(e.size()));
    fit[d.channels[c]] = ScoreChannel(ym, ym + em).fit_percent;
  }
  return fit;
}

double MeanSquaredError(const MeasuredData& d, const Part& part, const Eigen::VectorXd& residual) {
  const auto channels = static_cast<Eigen::Index>(d.channels.size());
  double sum = 0.0;
  long count = 0;
  for (Eigen::Index k = part.begin; k < part.end; ++k)
    for (Eigen::Index c = 0; c < channels; ++c)
      if (d.sampled(k, c)) {
        sum +=
            residual((k - part.begin) * channels + c) * residual((k - part.begin) * channels + c);
        ++count;
      }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

std::vector<ChannelResidual> AnalyseResiduals(const MeasuredData& d,
                                              const Eigen::VectorXd& residual,
                                              const std::vector<std::string>& input_names,
                                              const Eigen::MatrixXd& free_run) {
  const auto channels = static_cast<Eigen::Index>(d.channels.size());
  const Eigen::Index n = d.rows();
  const Eigen::Map<const Eigen::VectorXd> t(d.times.data(), n);
  const double dt = MedianInterval(t);
  const int max_lag = std::max(1, static_cast<int>(std::round(kMaxLagS / dt)));

  // Regressors over all rows: heading, speed, inputs.
  std::map<std::string, Eigen::VectorXd> regressors;
  if (d.heading_channel >= 0) {
    regressors["cos_heading"] = d.measured.col(d.heading_channel).array().cos();
    regressors["sin_heading"] = d.measured.col(d.heading_channel).array().sin();
  }
  for (const char* speed : {"u", "U", "v"}) {
    for (Eigen::Index c = 0; c < channels; ++c)
      if (d.channels[c] == speed) regressors[speed] = d.measured.col(c);
  }
  std::vector<Eigen::VectorXd> inputs(input_names.size(), Eigen::VectorXd(n));
  for (Eigen::Index k = 0; k < n; ++k) {
    const double* u = d.inputs.At(d.times[k]);
    for (size_t i = 0; i < input_names.size(); ++i) inputs[i](k) = u[i];
  }
  for (size_t i = 0; i < input_names.size(); ++i) regressors[input_names[i]] = inputs[i];

  std::vector<ChannelResidual> out;
  for (Eigen::Index c = 0; c < channels; ++c) {
    ChannelResidual r;
    r.channel = d.channels[c];
    Eigen::VectorXd e(n), model(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      e(k) = -residual(k * channels + c) * d.scale[c];
      model(k) = d.measured(k, c) - e(k);
    }
    const std::vector<Eigen::Index> rows = SampledRows(d, static_cast<int>(c));
    const Eigen::VectorXd y = Gather(d.measured.col(c), rows), es = Gather(e, rows);
    r.segment_fit_percent = ScoreChannel(y, y - es).fit_percent;
    r.bias = es.size() > 0 ? es.mean() : 0.0;
    {
      const int state = d.channel_state[c];
      const Eigen::Index m = std::min<Eigen::Index>(free_run.rows(), n);
      std::vector<Eigen::Index> in_run;
      for (Eigen::Index k : rows)
        if (k < m) in_run.push_back(k);
      Eigen::VectorXd sim = Gather(free_run.col(state), in_run);
      const Eigen::VectorXd meas = Gather(d.measured.col(c), in_run);
      // A run that diverged early is scored as predicting zero from there.
      Eigen::VectorXd full = Eigen::VectorXd::Zero(y.size());
      full.head(sim.size()) = sim;
      r.free_run_fit_percent = ScoreChannel(y, full).fit_percent;
    }
    // Drift: the mean within-segment slope of e.
    double slope_sum = 0.0;
    int segments = 0;
    for (size_t s = 0; s < d.all.starts.size(); ++s) {
      const auto [a, b] = SegmentRows(d.all, s);
      double st = 0, se = 0, stt = 0, ste = 0;
      long m = 0;
      for (Eigen::Index k = a; k < b; ++k) {
        if (!d.sampled(k, c)) continue;
        const double tk = t(k) - t(a);
        st += tk, se += e(k), stt += tk * tk, ste += tk * e(k), ++m;
      }
      const double den = m * stt - st * st;
      if (m > 2 && den > 0) slope_sum += (m * ste - st * se) / den, ++segments;
    }
    r.drift_per_s = segments > 0 ? slope_sum / segments : 0.0;
    if (rows.size() > static_cast<size_t>(2 * max_lag + 2)) {
      r.lag_s = EstimateLag(Gather(model, rows), y, max_lag).lag * dt;
      for (size_t i = 0; i < input_names.size(); ++i) {
        const LagEstimate lag = EstimateLag(Gather(inputs[i], rows), es, max_lag);
        r.inputs.push_back({input_names[i], lag.lag * dt, lag.correlation});
      }
    }
    for (const auto& [name, values] : regressors)
      r.regressors[name] = Correlation(Gather(values, rows), es);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace usvid::diagnosis
