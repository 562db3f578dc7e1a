// EffectFitter for a compile-time vessel V. After a coarse grid on the reset run: Ceres
// (Levenberg-Marquardt, automatic derivatives through every segment's rollout, each segment's
// initial state free; segment_cost.h) for the smooth effects, NLopt (DIRECT-L, then Sbplx from
// its best point) on the reset run for input delay and saturation. All minimise the mean squared
// normalised residual of the training part within the effect's bounds; scoring then estimates
// the initial states with the sizes held.
#pragma once

#include <ceres/ceres.h>

#include <nlopt.hpp>
#include <numbers>

#include "core/check.h"
#include "diagnosis/effect_fitter.h"
#include "diagnosis/reset_rollout.h"
#include "diagnosis/segment_cost.h"
#include "methods/parameter_sd.h"
#include "methods/schur_covariance.h"

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
                            const std::optional<Effect>& effect) const override {
    // No effect: the base model (its inertia scale set to what it already is).
    const EffectKind kind = effect ? effect->kind : EffectKind::kInertia;
    std::vector<double> theta = {data.base.inertia_scale};
    if (effect) {
      theta.clear();
      for (const std::string& name : SizeNames(kind)) theta.push_back(effect->at(name));
    }
    int input = -1;
    if (effect && !effect->inputs.empty()) {
      const std::vector<std::string> names = InputNames();
      input = static_cast<int>(std::ranges::find(names, effect->inputs[0]) - names.begin());
    }
    const EffectSearch search = kind == EffectKind::kMissingTerm
                                    ? SearchForTerm(*effect, StateNames(), InputNames())
                                    : SearchFor(kind, data, V::kYawInput, input);
    EffectFit unused;
    return theta.size() == 1
               ? SolveSegments<1>(data, part, ToParams(params), search, theta, false, unused)
               : SolveSegments<2>(data, part, ToParams(params), search, theta, false, unused);
  }

  Eigen::VectorXd ResetResiduals(const MeasuredData& data, const Part& part,
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
      EffectValues<double> e = data.base;
      ApplySizes(search, theta.data(), e);
      Eigen::VectorXd r(ResidualCount(data, train));
      ResetRollout<V, double>(data, train, p, e, r.data());
      return r.squaredNorm() / std::max<Eigen::Index>(1, r.size());
    };
    EffectFit fit;
    // A coarse grid first (the cost of an unstable hull has local minima), then Ceres from its
    // best with every segment's initial state free, or NLopt on the reset cost.
    std::vector<double> theta = BestStart(cost, StartGrid(search));
    if (!search.smooth) SolveNlopt(cost, search, theta, fit);
    const bool free = search.smooth;
    const Eigen::VectorXd r = search.size() == 1
                                  ? SolveSegments<1>(data, train, p, search, theta, free, fit)
                                  : SolveSegments<2>(data, train, p, search, theta, free, fit);
    fit.effect = EffectOf(search, theta, InputNames());
    fit.train_cost = r.squaredNorm() / std::max<Eigen::Index>(1, r.size());
    return fit;
  }

 private:
  static std::vector<std::string> InputNames() {
    return {V::kInputNames.begin(), V::kInputNames.end()};
  }
  static std::vector<std::string> StateNames() {
    return {V::kStateNames.begin(), V::kStateNames.end()};
  }

  static Params ToParams(const std::vector<double>& v) {
    USVID_CHECK(static_cast<int>(v.size()) == V::kParams, "one value per vessel parameter");
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
            grid.push_back({speed * std::cos(k * std::numbers::pi / 4),
                            speed * std::sin(k * std::numbers::pi / 4)});
        break;
      case EffectKind::kActuatorLag:
      case EffectKind::kInertia:
      case EffectKind::kDamping:
      case EffectKind::kResistance:
        for (int k = 0; k <= 8; ++k) grid.push_back({lo * std::pow(hi / lo, k / 8.0)});
        break;
      case EffectKind::kInputBias:
      case EffectKind::kSensorBias:
        for (double f : {0.01, 0.03, 0.1, 0.3})
          for (double sign : {-1.0, 1.0}) grid.push_back({sign * f * hi});
        break;
      case EffectKind::kSurgeForce:
        for (double a : {0.001, 0.003, 0.01, 0.03, 0.1})
          for (double sign : {-1.0, 1.0}) grid.push_back({sign * a});
        break;
      case EffectKind::kMissingTerm:
        for (double f : {0.0, 0.5, 2.0}) grid.push_back({f * search.start[0]});
        break;
      case EffectKind::kWind:
        for (double scale : {-1.0, 0.5, 1.0, 2.0}) grid.push_back({scale});
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

  // Every segment's initial state estimated (states the data do not measure held), theta
  // fitted too when `free_theta`; returns the residuals of the part at the solution.
  template <int K>
  static Eigen::VectorXd SolveSegments(const MeasuredData& data, const Part& part, const Params& p,
                                       const EffectSearch& search, std::vector<double>& theta,
                                       bool free_theta, EffectFit& fit) {
    constexpr int S = V::kStates;
    Eigen::VectorXd residual(ResidualCount(data, part));
    std::vector<std::array<double, S>> x0;
    {
      EffectValues<double> e = data.base;
      ApplySizes(search, theta.data(), e);
      ResetRollout<V, double>(data, part, p, e, residual.data(), &x0);
    }
    ceres::Problem problem;
    problem.AddParameterBlock(theta.data(), K);
    if (free_theta) {
      for (int i = 0; i < K; ++i) {
        problem.SetParameterLowerBound(theta.data(), i, search.lower[i]);
        problem.SetParameterUpperBound(theta.data(), i, search.upper[i]);
      }
    } else {
      problem.SetParameterBlockConstant(theta.data());
    }
    std::vector<int> held;
    for (int i = 0; i < S; ++i)
      if (data.state_channel[i] < 0) held.push_back(i);
    for (size_t s = 0; s < part.starts.size(); ++s) {
      problem.AddResidualBlock(SegmentCost<V, K>::Create(data, part, s, p, search), nullptr,
                               theta.data(), x0[s].data());
      if (held.size() == static_cast<size_t>(S)) {
        problem.SetParameterBlockConstant(x0[s].data());
      } else if (!held.empty()) {
        problem.SetManifold(x0[s].data(), new ceres::SubsetManifold(S, held));
      }
    }
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_SCHUR;
    options.max_num_iterations = 20;
    options.function_tolerance = 1e-7;
    options.parameter_tolerance = 1e-10;
    options.num_threads = 1;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    if (free_theta) {
      fit.evaluations = static_cast<int>(summary.iterations.size());
      fit.message = std::string("ceres ") +
                    ceres::TerminationTypeToString(summary.termination_type) + ": " +
                    summary.message;
      Eigen::MatrixXd c;  // segment by segment: a long log's Jacobian is never whole
      if (SchurCovariance(problem, theta.data(), &c)) fit.sd = ParameterSds(c.data(), K, summary);
    }
    EffectValues<double> e = data.base;
    ApplySizes(search, theta.data(), e);
    const EffectPlant<V, double> plant(data, p, e);
    for (size_t s = 0; s < part.starts.size(); ++s) {
      const Eigen::Index a = part.starts[s];
      SegmentRollout<V, double>(data, part, s, plant, x0[s].data(),
                                residual.data() + (a - part.begin) * data.channels.size());
    }
    return residual;
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

template <Vessel V>
std::unique_ptr<const EffectFitter> NewEffectFitter() {
  return std::make_unique<const TypedEffectFitter<V>>();
}

}  // namespace usvid::diagnosis
