// EffectFitter for a compile-time vessel V: Ceres (Levenberg-Marquardt, automatic derivatives
// through the whole segment-reset rollout) for the smooth effects, NLopt (DIRECT-L, then Sbplx
// from its best point) for input delay and saturation. Both minimise the mean squared
// normalised residual of the training part within the effect's bounds.
#pragma once

#include <ceres/ceres.h>

#include <nlopt.hpp>

#include "diagnosis/effect_fitter.h"
#include "diagnosis/reset_rollout.h"

namespace usvid::diagnosis {

template <Vessel V>
class TypedEffectFitter : public EffectFitter {
 public:
  using Params = std::array<double, V::kParams>;

  std::string_view Name() const override { return V::kName; }
  int YawInput() const override { return V::kYawInput; }

  void Derivative(const std::vector<double>& params, const double* x, const double* u,
                  double* dx) const override {
    V::template Derivative<double>(x, u, ToParams(params).data(), Environment<double>{}, dx);
  }

  Eigen::VectorXd Residuals(const MeasuredData& data, const Part& part,
                            const std::vector<double>& params,
                            const EffectValues<double>& effects) const override {
    Eigen::VectorXd r(ResidualCount(data, part));
    ResetRollout<V, double>(data, part, ToParams(params), effects, r.data());
    return r;
  }

  EffectFit Fit(const MeasuredData& data, const Part& train, const std::vector<double>& params,
                const EffectSearch& search) const override {
    const Params p = ToParams(params);
    auto cost = [&](const std::vector<double>& theta) {
      EffectValues<double> e;
      ApplySizes(search.kind, theta.data(), e);
      Eigen::VectorXd r(ResidualCount(data, train));
      ResetRollout<V, double>(data, train, p, e, r.data());
      return r.squaredNorm() / std::max<Eigen::Index>(1, r.size());
    };
    EffectFit fit;
    // A coarse grid first (the cost of an unstable hull has local minima), Ceres from its best.
    std::vector<double> theta = BestStart(cost, StartGrid(search));
    if (search.smooth) {
      if (search.size() == 1) {
        SolveCeres<1>(data, train, p, search, theta, fit);
      } else {
        SolveCeres<2>(data, train, p, search, theta, fit);
      }
    } else {
      SolveNlopt(cost, search, theta, fit);
    }
    fit.effect = EffectOf(search.kind, theta);
    fit.train_cost = cost(theta);
    return fit;
  }

 private:
  static Params ToParams(const std::vector<double>& v) {
    if (static_cast<int>(v.size()) != V::kParams) std::abort();
    Params p;
    std::copy(v.begin(), v.end(), p.begin());
    return p;
  }

  // Starting points: the neutral value and a grid over the bounds (geometric for scales and
  // time constants, symmetric about zero for biases; a ring of directions for the current).
  static std::vector<std::vector<double>> StartGrid(const EffectSearch& search) {
    std::vector<std::vector<double>> grid = {search.start};
    const double lo = search.lower[0], hi = search.upper[0];
    switch (search.kind) {
      case EffectKind::kCurrent:
        for (double speed : {0.3, 1.0})
          for (int k = 0; k < 8; ++k)
            grid.push_back({speed * std::cos(k * M_PI / 4), speed * std::sin(k * M_PI / 4)});
        break;
      case EffectKind::kActuatorLag:
      case EffectKind::kInertia:
      case EffectKind::kDamping:
        for (int k = 0; k <= 8; ++k) grid.push_back({lo * std::pow(hi / lo, k / 8.0)});
        break;
      case EffectKind::kInputBias:
      case EffectKind::kSensorBias:
        for (double f : {0.01, 0.03, 0.1, 0.3})
          for (double sign : {-1.0, 1.0}) grid.push_back({sign * f * hi});
        break;
      case EffectKind::kInputDelay:
      case EffectKind::kSaturation:
        break;
    }
    return grid;
  }

  template <typename Cost>
  static std::vector<double> BestStart(const Cost& cost,
                                       const std::vector<std::vector<double>>& starts) {
    std::vector<double> best = starts[0];
    double best_cost = INFINITY;
    for (const std::vector<double>& s : starts) {
      const double c = cost(s);
      if (c < best_cost) best_cost = c, best = s;
    }
    return best;
  }

  template <int K>
  struct RolloutCost {
    const MeasuredData* data;
    const Part* part;
    Params params;
    EffectKind kind;
    template <typename T>
    bool operator()(const T* theta, T* residual) const {
      EffectValues<T> e;
      ApplySizes(kind, theta, e);
      ResetRollout<V, T>(*data, *part, params, e, residual);
      return true;
    }
  };

  template <int K>
  static void SolveCeres(const MeasuredData& data, const Part& train, const Params& p,
                         const EffectSearch& search, std::vector<double>& theta, EffectFit& fit) {
    ceres::Problem problem;
    const int residuals = static_cast<int>(ResidualCount(data, train));
    auto* cost = new ceres::AutoDiffCostFunction<RolloutCost<K>, ceres::DYNAMIC, K>(
        new RolloutCost<K>{&data, &train, p, search.kind}, residuals);
    problem.AddResidualBlock(cost, nullptr, theta.data());
    for (int i = 0; i < K; ++i) {
      problem.SetParameterLowerBound(theta.data(), i, search.lower[i]);
      problem.SetParameterUpperBound(theta.data(), i, search.upper[i]);
    }
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_QR;
    options.max_num_iterations = 40;
    options.function_tolerance = 1e-10;
    options.parameter_tolerance = 1e-10;
    options.num_threads = 1;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    fit.evaluations = static_cast<int>(summary.iterations.size());
    fit.message = std::string("ceres ") + ceres::TerminationTypeToString(summary.termination_type) + ": " +
                  summary.message;
    ceres::Covariance::Options co;
    ceres::Covariance covariance(co);
    std::vector<std::pair<const double*, const double*>> blocks = {{theta.data(), theta.data()}};
    if (covariance.Compute(blocks, &problem)) {
      double c[K * K];
      covariance.GetCovarianceBlock(theta.data(), theta.data(), c);
      const double s2 = 2.0 * summary.final_cost / std::max(1, residuals - K);
      for (int i = 0; i < K; ++i) fit.sd.push_back(std::sqrt(std::max(0.0, c[i * K + i] * s2)));
    }
  }

  template <typename Cost>
  static void SolveNlopt(const Cost& cost, const EffectSearch& search, std::vector<double>& theta,
                         EffectFit& fit) {
    struct Context {
      const Cost* cost;
      int evaluations = 0;
      double best = INFINITY;
      std::vector<double> best_x;
    } context{&cost, 0, INFINITY, {}};
    auto objective = [](const std::vector<double>& x, std::vector<double>&, void* data) {
      auto* c = static_cast<Context*>(data);
      ++c->evaluations;
      const double value = (*c->cost)(x);
      if (value < c->best) c->best = value, c->best_x = x;
      return value;
    };
    const auto n = static_cast<unsigned>(search.size());
    std::string how;
    for (nlopt::algorithm algorithm : {nlopt::GN_DIRECT_L, nlopt::LN_SBPLX}) {
      nlopt::opt opt(algorithm, n);
      opt.set_lower_bounds(search.lower);
      opt.set_upper_bounds(search.upper);
      opt.set_min_objective(objective, &context);
      opt.set_maxeval(algorithm == nlopt::GN_DIRECT_L ? 48 : 24);
      opt.set_xtol_abs(1e-3);
      if (algorithm == nlopt::LN_SBPLX) {
        std::vector<double> step(n);
        for (unsigned i = 0; i < n; ++i) step[i] = 0.02 * (search.upper[i] - search.lower[i]);
        opt.set_initial_step(step);
      }
      double value = 0.0;
      try {
        if (!context.best_x.empty()) theta = context.best_x;
        const nlopt::result result = opt.optimize(theta, value);
        how += std::string(how.empty() ? "" : ", ") + opt.get_algorithm_name() + ": " +
               std::to_string(static_cast<int>(result));
      } catch (const std::exception& e) {
        how += std::string(how.empty() ? "" : ", ") + "nlopt failed: " + e.what();
      }
    }
    if (!context.best_x.empty()) theta = context.best_x;
    fit.evaluations = context.evaluations;
    fit.message = how;
  }
};

}  // namespace usvid::diagnosis
