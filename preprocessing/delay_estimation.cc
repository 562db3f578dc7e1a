#include "preprocessing/delay_estimation.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <nlopt.hpp>

#include "core/error.h"
#include "preprocessing/cross_correlation.h"

namespace usvid {
namespace {

int MaxShift(const DelayProblem& p, double max_delay_s) {
  if (!(p.dt > 0)) throw InputError("delay estimation: the sample interval must be positive");
  if (p.states.empty() || p.states.size() != p.derivatives.size() || p.inputs.empty())
    throw InputError("delay estimation: needs states, their derivatives and inputs");
  const int n = static_cast<int>(std::floor(max_delay_s / p.dt + 1e-9));
  if (n < 1 || n * 4 >= p.states[0].values.size())
    throw InputError(
        "delay estimation: the delay limit must cover at least one sample and "
        "less than a quarter of the data");
  return n;
}

// Mean (1 - R^2) over the states of the equation-error fit with input i shifted by shift[i]
// samples, on the rows [n_max, N).
class ShiftedFit {
 public:
  ShiftedFit(const DelayProblem& p, int n_max) : p_(p), n_max_(n_max) {
    const RegressorLibrary lib = BuildLibrary(p.states, {}, p.library);
    rows_ = lib.columns.rows() - n_max;
    base_ = lib.columns.bottomRows(rows_);
    targets_.resize(rows_, static_cast<Eigen::Index>(p.derivatives.size()));
    for (size_t j = 0; j < p.derivatives.size(); ++j)
      targets_.col(static_cast<Eigen::Index>(j)) = p.derivatives[j].values.tail(rows_);
  }

  double Cost(const std::vector<int>& shift) const {
    Eigen::MatrixXd a(rows_, base_.cols() + static_cast<Eigen::Index>(p_.inputs.size()));
    a.leftCols(base_.cols()) = base_;
    for (size_t i = 0; i < p_.inputs.size(); ++i)
      a.col(base_.cols() + static_cast<Eigen::Index>(i)) =
          p_.inputs[i].values.segment(n_max_ - shift[i], rows_);
    Eigen::VectorXd scale = (a.colwise().squaredNorm() / static_cast<double>(rows_)).cwiseSqrt();
    for (Eigen::Index c = 0; c < scale.size(); ++c)
      if (scale(c) == 0.0) scale(c) = 1.0;
    const Eigen::MatrixXd w =
        (a * scale.cwiseInverse().asDiagonal()).colPivHouseholderQr().solve(targets_);
    const Eigen::MatrixXd residual = targets_ - (a * scale.cwiseInverse().asDiagonal()) * w;
    double cost = 0.0;
    for (Eigen::Index j = 0; j < targets_.cols(); ++j) {
      const double sst = (targets_.col(j).array() - targets_.col(j).mean()).square().sum();
      cost += sst > 0 ? residual.col(j).squaredNorm() / sst : 0.0;
    }
    return cost / static_cast<double>(targets_.cols());
  }

 private:
  const DelayProblem& p_;
  int n_max_;
  Eigen::Index rows_ = 0;
  Eigen::MatrixXd base_, targets_;
};

// Sub-sample position of the minimum of a sampled cost, by a parabola through its neighbours.
double RefineMinimum(const std::vector<double>& cost, int best) {
  if (best <= 0 || best + 1 >= static_cast<int>(cost.size())) return best;
  const double l = cost[best - 1], c = cost[best], r = cost[best + 1];
  const double curvature = l - 2 * c + r;
  return curvature > 0 ? best + 0.5 * (l - r) / curvature : best;
}

}  // namespace

DelayEstimate CrossCorrelationDelay(const DelayProblem& p, double max_delay_s) {
  const int n_max = MaxShift(p, max_delay_s);
  auto increments = [](const Eigen::VectorXd& x) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(x.size());
    d.tail(x.size() - 1) = x.tail(x.size() - 1) - x.head(x.size() - 1);
    return d;
  };
  DelayEstimate est;
  est.method = "cross-correlation";
  double best_overall = -1.0;
  for (const NamedSignal& u : p.inputs) {
    const Eigen::VectorXd du = increments(u.values);
    double best = -1.0, lag = 0.0;
    for (const NamedSignal& dx : p.derivatives) {
      const Eigen::VectorXd ddx = increments(dx.values);
      for (double sign : {1.0, -1.0}) {
        const LagEstimate l = EstimateLag(du, sign * ddx, n_max);
        if (l.integer_lag >= 0 && l.correlation > best) {
          best = l.correlation;
          lag = std::max(0.0, l.lag);
        }
      }
    }
    est.per_input_s.push_back(lag * p.dt);
    if (best > best_overall) {
      best_overall = best;
      est.delay_s = lag * p.dt;
    }
  }
  return est;
}

DelayEstimate ScanDelay(const DelayProblem& p, double max_delay_s, bool per_input) {
  const int n_max = MaxShift(p, max_delay_s);
  const ShiftedFit fit(p, n_max);
  const size_t m = p.inputs.size();
  DelayEstimate est;
  est.method = per_input ? "scan (per input)" : "scan";
  std::vector<int> shift(m, 0);
  int best = 0;
  for (int n = 0; n <= n_max; ++n) {
    std::fill(shift.begin(), shift.end(), n);
    est.scan_delays_s.push_back(n * p.dt);
    est.scan_cost.push_back(fit.Cost(shift));
    if (est.scan_cost.back() < est.scan_cost[best]) best = n;
  }
  est.delay_s = RefineMinimum(est.scan_cost, best) * p.dt;
  est.per_input_s.assign(m, est.delay_s);
  if (!per_input) return est;

  std::vector<int> shifts(m, best);
  std::vector<double> refined(m, est.delay_s);
  for (int sweep = 0; sweep < 2; ++sweep) {
    for (size_t i = 0; i < m; ++i) {
      std::vector<double> cost;
      int best_i = 0;
      for (int n = 0; n <= n_max; ++n) {
        shifts[i] = n;
        cost.push_back(fit.Cost(shifts));
        if (cost.back() < cost[best_i]) best_i = n;
      }
      shifts[i] = best_i;
      refined[i] = RefineMinimum(cost, best_i) * p.dt;
    }
  }
  est.per_input_s = refined;
  return est;
}

DelayEstimate ContinuousDelay(const std::function<double(const std::vector<double>&)>& cost,
                              int count, double max_delay_s, const std::vector<double>& start,
                              int max_evaluations) {
  if (count < 1 || !(max_delay_s > 0))
    throw InputError("delay estimation: needs at least one delay and a positive limit");
  struct Data {
    const std::function<double(const std::vector<double>&)>* cost;
    std::vector<double> best_x;
    double best_f = INFINITY;
  } data{&cost, start, INFINITY};
  auto objective = [](const std::vector<double>& x, std::vector<double>&, void* d) {
    auto* data = static_cast<Data*>(d);
    const double f = (*data->cost)(x);
    if (f < data->best_f) {
      data->best_f = f;
      data->best_x = x;
    }
    return std::isfinite(f) ? f : 1e300;
  };
  std::vector<double> x = start;
  x.resize(count, 0.5 * max_delay_s);
  for (double& v : x) v = std::clamp(v, 0.0, max_delay_s);
  for (nlopt::algorithm algorithm : {nlopt::GN_DIRECT_L, nlopt::LN_SBPLX}) {
    nlopt::opt opt(algorithm, static_cast<unsigned>(count));
    opt.set_lower_bounds(std::vector<double>(count, 0.0));
    opt.set_upper_bounds(std::vector<double>(count, max_delay_s));
    opt.set_min_objective(objective, &data);
    opt.set_maxeval(max_evaluations / 2);
    opt.set_xtol_abs(1e-4);
    if (algorithm == nlopt::LN_SBPLX) opt.set_initial_step(0.02 * max_delay_s);
    double f = 0.0;
    if (!data.best_x.empty() && std::isfinite(data.best_f)) x = data.best_x;
    try {
      opt.optimize(x, f);
    } catch (const std::exception&) {
      // NLopt stops on round-off or a flat cost; the best point seen is kept below.
    }
  }
  DelayEstimate est;
  est.method = "continuous (NLopt DIRECT-L + Sbplx)";
  est.per_input_s = data.best_x;
  est.delay_s = data.best_x.empty() ? 0.0 : data.best_x[0];
  return est;
}

}  // namespace usvid
