// The rollouts the diagnosis scores with (diagnosis/reset_rollout.h): the exact model with the
// exact effect reproduces clean data, the delayed input is continuous in the delay, the actuator
// memory at a segment start is the first-order filter of the commands, and the Jet derivative
// of a segment with respect to an effect size matches central differences.
#include "diagnosis/reset_rollout.h"

#include <gtest/gtest.h>

#include <cmath>

#include "diagnosis/effect_search.h"
#include "diagnosis/segment_cost.h"
#include "maneuvers/maneuver_factory.h"
#include "simulators/odin3dof.h"

namespace usvid::diagnosis {
namespace {

Dataset CleanRun(const std::vector<Effect>& effects, const std::string& maneuver = "random-steps") {
  const VesselSimulator& sim = FindVessel("odin3dof");
  auto m = MakeManeuver(maneuver, sim.Info().actuation, 120.0, 3);
  return sim.RunManeuver(*m, sim.Info().default_params, ValuesOf(effects), RunOptions{}).data;
}

std::array<double, Odin3Dof::kParams> Defaults() { return Odin3Dof::kDefaultParams; }

double Rms(const Eigen::VectorXd& r) { return std::sqrt(r.squaredNorm() / r.size()); }

TEST(ResetRolloutTest, ExactEffectReproducesCleanData) {
  // Data with a 0.4 m/s current: the nominal model misses it, the model with it does not.
  const Effect current{EffectKind::kCurrent, {{"current_north", 0.3}, {"current_east", -0.25}}};
  const Dataset data = CleanRun({current});
  const VesselSimulator& sim = FindVessel("odin3dof");
  const MeasuredData d = PrepareMeasuredData(data, sim, sim.Info().default_params, {});
  Eigen::VectorXd nominal(ResidualCount(d, d.all)), exact(ResidualCount(d, d.all));
  ResetRollout<Odin3Dof, double>(d, d.all, Defaults(), EffectValues<double>{}, nominal.data());
  ResetRollout<Odin3Dof, double>(d, d.all, Defaults(), ValuesOf({current}), exact.data());
  EXPECT_LT(Rms(exact), 2e-3) << "normalised residual of the exact model";
  EXPECT_GT(Rms(nominal), 20 * Rms(exact));
}

TEST(ResetRolloutTest, DelayedMeanIsContinuousInTheDelayAndZeroOrderHoldOnTheGrid) {
  InputTrack track(1);
  for (int k = 0; k < 10; ++k) track.Append(0.1 * k, std::vector<double>{k % 2 ? 1.0 : 0.0});
  double on_grid = 0.0, a = 0.0, b = 0.0;
  InputTrack::Cursor cursor;
  // A delay of one whole sample gives the previous sample's value.
  track.DelayedMean(0.5, 0.1, 0.1, {}, &on_grid, cursor);
  EXPECT_DOUBLE_EQ(on_grid, 0.0);  // sample 4
  // Half a sample: the mean of the two commands in force over the step.
  track.DelayedMean(0.5, 0.1, 0.05, {}, &a, cursor);
  EXPECT_NEAR(a, 0.5, 1e-12);
  track.DelayedMean(0.5, 0.1, 0.05 + 1e-6, {}, &b, cursor);
  EXPECT_NEAR(a, b, 1e-4);
}

TEST(ResetRolloutTest, LagStateIsTheFirstOrderFilterOfAStep) {
  // A step of tau_n at t = 0 through a 2 s lag: x(t) = u (1 - exp(-t / 2)) from the previous
  // command 0.
  Dataset data(Eigen::VectorXd::LinSpaced(201, 0.0, 10.0));
  for (const char* s : {"north", "east", "psi", "u", "v", "r"})
    data.Set(s, Eigen::VectorXd::LinSpaced(201, 0.0, 1.0));
  data.Set("tau_x", Eigen::VectorXd::Zero(201));
  data.Set("tau_y", Eigen::VectorXd::Zero(201));
  Eigen::VectorXd tau_n = Eigen::VectorXd::Constant(201, 1000.0);
  tau_n(0) = 0.0;
  data.Set("tau_n", tau_n);
  const VesselSimulator& sim = FindVessel("odin3dof");
  const MeasuredData d = PrepareMeasuredData(data, sim, sim.Info().default_params, {});
  EffectValues<double> e;
  e.lag_time_constant_s = 2.0;
  const EffectPlant<Odin3Dof, double> plant(d, Defaults(), e);
  std::array<double, 3> lag;
  LagStatesAt<Odin3Dof, double>(d, 0, 120, plant, lag.data());
  const double t = d.times[120] - d.times[1];  // the step is in force from row 1
  EXPECT_NEAR(lag[2], 1000.0 * (1.0 - std::exp(-t / 2.0)), 1.0);
}

TEST(ResetRolloutTest, SegmentJetDerivativeMatchesCentralDifferences) {
  const Dataset data = CleanRun({}, "multisine");
  const VesselSimulator& sim = FindVessel("odin3dof");
  const MeasuredData d = PrepareMeasuredData(data, sim, sim.Info().default_params, {});
  const EffectSearch search = SearchFor(EffectKind::kInertia, d, Odin3Dof::kYawInput);
  SegmentCost<Odin3Dof, 1> cost{&d, &d.train, 1, Defaults(), &search};
  std::array<double, 6> x0;
  for (int i = 0; i < 6; ++i) x0[i] = d.fallback_states(d.train.starts[1], i);
  const int n = cost.Residuals();
  using J = ceres::Jet<double, 7>;
  std::array<J, 1> theta = {J(1.3, 0)};
  std::array<J, 6> x0j;
  for (int i = 0; i < 6; ++i) x0j[i] = J(x0[i], i + 1);
  std::vector<J> rj(n);
  cost(theta.data(), x0j.data(), rj.data());
  const double h = 1e-6;
  std::vector<double> plus(n), minus(n);
  const double tp = 1.3 + h, tm = 1.3 - h;
  cost(&tp, x0.data(), plus.data());
  cost(&tm, x0.data(), minus.data());
  double worst = 0.0, scale = 0.0;
  for (int k = 0; k < n; ++k) {
    const double fd = (plus[k] - minus[k]) / (2 * h);
    worst = std::max(worst, std::abs(rj[k].v[0] - fd));
    scale = std::max(scale, std::abs(fd));
  }
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(worst, 1e-5 * scale);
}

}  // namespace
}  // namespace usvid::diagnosis
