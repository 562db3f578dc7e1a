// Differentiable simulation (issue 3 acceptance): the Jacobian of a 200-step odin3dof rollout
// with respect to every parameter, carried by ceres::Jet through RK4, agrees with central
// differences of the double rollout to 1e-6 relative; the same holds for the effect sizes that
// diagnosis fits (current, input bias, inertia and damping scales, actuator lag).
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <random>

#include "simulation/open_loop.h"
#include "simulators/odin3dof.h"

namespace usvid {
namespace {

class RolloutJacobianTest : public ::testing::Test {
 protected:
  static constexpr int kSteps = 200;
  static constexpr int kN = Plant<Odin3Dof>::kStates;

  void SetUp() override {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> tx(8000, 30000), ty(-1500, 1500), tn(-4000, 4000);
    double level[3] = {tx(rng), ty(rng), tn(rng)};
    for (int k = 0; k <= kSteps; ++k) {
      if (k % 40 == 0) level[0] = tx(rng), level[1] = ty(rng), level[2] = tn(rng);
      track_.Append(k * 0.05, level);
      setup_.times.push_back(k * 0.05);
    }
    setup_.inputs = &track_;
    setup_.max_step = 0.05;
    x0_.fill(0.0);
    x0_[3] = 7.0;
    Plant<Odin3Dof>::InitialLagState(track_.At(0.0), x0_.data());
    limits_.fill(INFINITY);
  }

  // States after every step, double precision, for parameters p and effects e.
  std::vector<double> Rollout(const std::array<double, Odin3Dof::kParams>& p,
                              const EffectValues<double>& e) const {
    std::vector<double> out(setup_.times.size() * kN);
    const size_t rows =
        RolloutOpenLoop<Odin3Dof, double>(setup_, x0_.data(), p.data(), e, limits_, out.data());
    EXPECT_EQ(rows, setup_.times.size());
    return out;
  }

  // Per parameter, ||J_jet - J_fd||_inf <= 1e-6 ||J_fd||_inf over all steps and states.
  static void ExpectColumnsAgree(const std::vector<std::vector<double>>& jet,
                                 const std::vector<std::vector<double>>& fd,
                                 const std::vector<std::string>& names) {
    for (size_t j = 0; j < names.size(); ++j) {
      double err = 0, scale = 0;
      for (size_t i = 0; i < fd[j].size(); ++i) {
        err = std::max(err, std::abs(jet[j][i] - fd[j][i]));
        scale = std::max(scale, std::abs(fd[j][i]));
      }
      EXPECT_GT(scale, 0.0) << names[j];
      EXPECT_LE(err, 1e-6 * scale) << names[j] << ": error " << err << ", scale " << scale;
    }
  }

  InputTrack track_{3};
  OpenLoopSetup setup_;
  std::array<double, kN> x0_;
  std::array<double, 3> limits_;
};

TEST_F(RolloutJacobianTest, ParameterJacobianMatchesCentralDifferences) {
  using J = ceres::Jet<double, Odin3Dof::kParams>;
  std::array<J, Odin3Dof::kParams> pj;
  for (int i = 0; i < Odin3Dof::kParams; ++i) pj[i] = J(Odin3Dof::kDefaultParams[i], i);
  std::array<J, kN> xj;
  for (int i = 0; i < kN; ++i) xj[i] = J(x0_[i]);
  std::vector<J> out(setup_.times.size() * kN);
  const size_t rows = RolloutOpenLoop<Odin3Dof, J>(setup_, xj.data(), pj.data(), EffectValues<J>{},
                                                   limits_, out.data());
  ASSERT_EQ(rows, setup_.times.size());

  std::vector<std::vector<double>> jet(Odin3Dof::kParams), fd(Odin3Dof::kParams);
  std::vector<std::string> names;
  for (int j = 0; j < Odin3Dof::kParams; ++j) {
    names.emplace_back(Odin3Dof::kParamNames[j]);
    const double h = 1e-5 * Odin3Dof::kDefaultParams[j];
    auto plus = Odin3Dof::kDefaultParams, minus = Odin3Dof::kDefaultParams;
    plus[j] += h;
    minus[j] -= h;
    const auto yp = Rollout(plus, {}), ym = Rollout(minus, {});
    for (size_t i = 0; i < out.size(); ++i) {
      if (static_cast<int>(i % kN) >= Odin3Dof::kStates) continue;  // lag memory: constant
      jet[j].push_back(out[i].v[j]);
      fd[j].push_back((yp[i] - ym[i]) / (2 * h));
    }
  }
  ExpectColumnsAgree(jet, fd, names);
}

TEST_F(RolloutJacobianTest, EffectJacobianMatchesCentralDifferences) {
  using J = ceres::Jet<double, 6>;
  EffectValues<double> base;
  base.current_north = 0.3;
  base.current_east = -0.2;
  base.input_bias = 200.0;
  base.inertia_scale = 1.1;
  base.damping_scale = 0.9;
  base.lag_time_constant_s = 0.8;
  EffectValues<J> ej;
  ej.current_north = J(base.current_north, 0);
  ej.current_east = J(base.current_east, 1);
  ej.input_bias = J(base.input_bias, 2);
  ej.inertia_scale = J(base.inertia_scale, 3);
  ej.damping_scale = J(base.damping_scale, 4);
  ej.lag_time_constant_s = J(base.lag_time_constant_s, 5);
  std::array<J, Odin3Dof::kParams> pj;
  for (int i = 0; i < Odin3Dof::kParams; ++i) pj[i] = J(Odin3Dof::kDefaultParams[i]);
  std::array<J, kN> xj;
  for (int i = 0; i < kN; ++i) xj[i] = J(x0_[i]);
  std::vector<J> out(setup_.times.size() * kN);
  const size_t rows =
      RolloutOpenLoop<Odin3Dof, J>(setup_, xj.data(), pj.data(), ej, limits_, out.data());
  ASSERT_EQ(rows, setup_.times.size());

  double EffectValues<double>::*fields[] = {
      &EffectValues<double>::current_north, &EffectValues<double>::current_east,
      &EffectValues<double>::input_bias,    &EffectValues<double>::inertia_scale,
      &EffectValues<double>::damping_scale, &EffectValues<double>::lag_time_constant_s};
  const std::vector<std::string> names = {"current_north", "current_east",  "input_bias",
                                          "inertia_scale", "damping_scale", "lag_time_constant"};
  std::vector<std::vector<double>> jet(6), fd(6);
  for (int j = 0; j < 6; ++j) {
    const double h = 1e-5 * std::max(1.0, std::abs(base.*fields[j]));
    EffectValues<double> plus = base, minus = base;
    plus.*fields[j] += h;
    minus.*fields[j] -= h;
    const auto yp = Rollout(Odin3Dof::kDefaultParams, plus);
    const auto ym = Rollout(Odin3Dof::kDefaultParams, minus);
    for (size_t i = 0; i < out.size(); ++i) {
      jet[j].push_back(out[i].v[j]);
      fd[j].push_back((yp[i] - ym[i]) / (2 * h));
    }
  }
  ExpectColumnsAgree(jet, fd, names);
}

// The adaptive Dormand-Prince rollout differentiates too: its step control decides on values
// only, so the Jet rollout's values equal the double rollout's to round-off, and its Jacobian
// matches central differences to the integrator's tolerance.
TEST_F(RolloutJacobianTest, AdaptiveRolloutJacobianMatchesCentralDifferences) {
  using J = ceres::Jet<double, Odin3Dof::kParams>;
  setup_.integrator = Integrator::kDormandPrince;
  std::array<J, Odin3Dof::kParams> pj;
  for (int i = 0; i < Odin3Dof::kParams; ++i) pj[i] = J(Odin3Dof::kDefaultParams[i], i);
  std::array<J, kN> xj;
  for (int i = 0; i < kN; ++i) xj[i] = J(x0_[i]);
  std::vector<J> out(setup_.times.size() * kN);
  const size_t rows = RolloutOpenLoop<Odin3Dof, J>(setup_, xj.data(), pj.data(), EffectValues<J>{},
                                                   limits_, out.data());
  ASSERT_EQ(rows, setup_.times.size());
  const auto base = Rollout(Odin3Dof::kDefaultParams, {});
  for (size_t i = 0; i < out.size(); ++i)
    EXPECT_NEAR(out[i].a, base[i], 1e-12 * (1 + std::abs(base[i])));
  for (int j = 0; j < Odin3Dof::kParams; ++j) {
    const double h = 1e-4 * Odin3Dof::kDefaultParams[j];
    auto plus = Odin3Dof::kDefaultParams, minus = Odin3Dof::kDefaultParams;
    plus[j] += h;
    minus[j] -= h;
    const auto yp = Rollout(plus, {}), ym = Rollout(minus, {});
    double err = 0, scale = 0;
    for (size_t i = 0; i < out.size(); ++i) {
      const double fd = (yp[i] - ym[i]) / (2 * h);
      err = std::max(err, std::abs(out[i].v[j] - fd));
      scale = std::max(scale, std::abs(fd));
    }
    EXPECT_LE(err, 1e-4 * scale) << Odin3Dof::kParamNames[j];
  }
}

}  // namespace
}  // namespace usvid
