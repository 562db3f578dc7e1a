// The steady state's sensitivity to the parameters (design/steady_state_sensitivity.h), by the
// implicit function theorem through Jets, against the steady state itself solved again with
// each parameter nudged (central differences): eb2dof at throttle 0.6 and nozzle 0.2 rad, where
// both the speed and the rate of turn settle.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <array>
#include <vector>

#include "design/steady_state_sensitivity.h"
#include "simulators/eb2dof.h"

namespace usvid::design {
namespace {

using V = Eb2Dof;

// U and r where eb2dof's derivatives vanish at (throttle, nozzle), by Newton's method.
Eigen::Vector2d SteadyState(const std::vector<double>& tau, const std::vector<double>& p) {
  std::vector<double> x = {0.0, 0.0, 0.0, 8.0, 0.1};
  for (int it = 0; it < 50; ++it) {
    const DerivativeJacobians d = DerivativeJacobiansAt<V>(x, tau, p);
    std::array<double, V::kStates> dx{};
    V::Derivative<double>(x.data(), tau.data(), p.data(), Environment<double>{}, dx.data());
    const Eigen::Vector2d step = d.fx.lu().solve(Eigen::Vector2d(dx[3], dx[4]));
    x[3] -= step(0);
    x[4] -= step(1);
  }
  return {x[3], x[4]};
}

TEST(SteadyStateSensitivityTest, MatchesTheSteadyStateSolvedAgain) {
  const std::vector<double> tau = {0.6, 0.2};
  const std::vector<double> p(V::kDefaultParams.begin(), V::kDefaultParams.end());
  const Eigen::Vector2d x0 = SteadyState(tau, p);
  ASSERT_GT(x0(0), 1.0);  // a speed, and a turn
  ASSERT_GT(x0(1), 0.01);
  const Eigen::MatrixXd s =
      SteadyStateSensitivity<V>({0.0, 0.0, 0.0, x0(0), x0(1)}, tau, p);
  ASSERT_EQ(s.rows(), 2);
  ASSERT_EQ(s.cols(), V::kParams);
  for (int j = 0; j < V::kParams; ++j) {
    const double h = 1e-5 * p[j];
    std::vector<double> up = p, down = p;
    up[j] += h;
    down[j] -= h;
    const Eigen::Vector2d fd = (SteadyState(tau, up) - SteadyState(tau, down)) / (2.0 * h);
    for (int i = 0; i < 2; ++i)
      EXPECT_NEAR(s(i, j), fd(i), 1e-5 * (1.0 + std::abs(fd(i)))) << V::kParamNames[j];
  }
  // The masses do not move a steady state.
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(s.col(j).norm(), 0.0, 1e-12) << V::kParamNames[j];
}

}  // namespace
}  // namespace usvid::design
