#include "methods/eb_lr/output_error.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace usvid::eb_lr {
namespace {

// x_i simulated over every run, at each sample after the run's start.
Eigen::VectorXd Simulate(const MassOutputErrorProblem& p, const Eigen::VectorXd& mass,
                         Eigen::Index rows) {
  const bool speed_equation = p.state == 0;
  const Eigen::VectorXd& own = speed_equation ? p.speed : p.rate;
  const Eigen::VectorXd& other = speed_equation ? p.rate : p.speed;
  const bool loss_term = speed_equation && p.loss_channel.size() > 0;
  auto f = [&](double y, double x, double u, double q) {
    const double speed = speed_equation ? y : x, rate = speed_equation ? x : y;
    const double loss = loss_term ? p.thrust_loss * q * speed : 0.0;
    return (u - loss - Combination(p.sigma_basis, p.sigma, speed, rate)) /
           Combination(p.mass_basis, mass, speed, rate);
  };
  Eigen::VectorXd out(rows);
  Eigen::Index row = 0;
  for (const SteadyWindow& run : p.runs) {
    double y = own(run.first);
    for (Eigen::Index k = run.first; k < run.last; ++k) {
      const double h = p.t(k + 1) - p.t(k), u = p.input(k), mid = 0.5 * (other(k) + other(k + 1));
      const double q = loss_term ? p.loss_channel(k) : 0.0;  // held, like the input
      const double k1 = f(y, other(k), u, q), k2 = f(y + 0.5 * h * k1, mid, u, q);
      const double k3 = f(y + 0.5 * h * k2, mid, u, q), k4 = f(y + h * k3, other(k + 1), u, q);
      y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      out(row++) = y;
    }
  }
  return out;
}

}  // namespace

MassOutputErrorFit FitMassByOutputError(const MassOutputErrorProblem& problem,
                                        Eigen::VectorXd start) {
  constexpr int kMaxIterations = 20;
  Eigen::Index rows = 0;
  for (const SteadyWindow& run : problem.runs) rows += run.last - run.first;
  Eigen::VectorXd measured(rows);
  rows = 0;
  for (const SteadyWindow& run : problem.runs)
    for (Eigen::Index k = run.first + 1; k <= run.last; ++k) measured(rows++) = problem.measured(k);

  MassOutputErrorFit fit{std::move(start)};
  Eigen::VectorXd y = Simulate(problem, fit.mass, rows);
  double cost = (measured - y).squaredNorm();
  while (std::isfinite(cost) && rows > 0 && fit.iterations < kMaxIterations) {
    ++fit.iterations;
    Eigen::MatrixXd jac(rows, fit.mass.size());
    for (Eigen::Index j = 0; j < fit.mass.size(); ++j) {
      Eigen::VectorXd m = fit.mass;
      const double h = 1e-6 * std::max(std::abs(m(j)), 1e-3 * fit.mass.cwiseAbs().maxCoeff());
      m(j) += h;
      jac.col(j) = (Simulate(problem, m, rows) - y) / h;
    }
    const Eigen::VectorXd step = jac.colPivHouseholderQr().solve(measured - y);
    bool improved = false;
    for (double f = 1.0; f > 1e-3 && !improved; f *= 0.5) {
      const Eigen::VectorXd m = fit.mass + f * step;
      const Eigen::VectorXd ym = Simulate(problem, m, rows);
      const double c = (measured - ym).squaredNorm();
      if (std::isfinite(c) && c <= cost) {
        improved = true;
        fit.mass = m;
        y = ym;
        cost = c;
      }
    }
    if (!improved || !step.allFinite() || step.norm() < 1e-9 * fit.mass.norm()) break;
  }
  fit.rms = rows > 0 ? std::sqrt(cost / static_cast<double>(rows)) : 0.0;
  return fit;
}

}  // namespace usvid::eb_lr
