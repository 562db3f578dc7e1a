// fossen-ceres on the jets' forces (methods/fossen_ceres/jet_force_model.h, issue 19): the
// equations written to model.json are the model's own dynamics; the resistance coefficient c(U)
// passes through its knots, is linear between them and held above the last; trained on 600 s of
// odin-hs random steps through `--forces waterjet`, the model free-runs a held-out random-step
// run across displacement, semi-displacement and planing with a fit of 90 % or more on u, v, r
// and 80 % or more in each regime, and c(U) is the simulator's resistance: the hump included.
#include "methods/fossen_ceres/jet_force_model.h"

#include <gtest/gtest.h>

#include <random>

#include "core/expression.h"
#include "methods/fossen_ceres/fossen_fit.h"
#include "metrics/evaluation.h"
#include "preprocessing/waterjet_forces.h"
#include "simulators/odin_hs.h"
#include "tests/support/synthetic_data.h"

namespace usvid {
namespace {

using fossen::JetForceModel;

std::array<double, JetForceModel::kParams> SomeParams(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.5, 1.5), sign(-1.0, 1.0);
  std::array<double, JetForceModel::kParams> p;
  for (int i = 0; i < JetForceModel::kParams; ++i)
    p[i] = JetForceModel::kStart[i] * unit(rng) + (JetForceModel::Signed(i) ? 300 * sign(rng) : 0);
  return p;
}

TEST(JetForceModelTest, WrittenEquationsAreTheModelsDynamics) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3, 19), v(-2, 2), r(-0.5, 0.5), f(-2e4, 2e4), q(0, 0.8);
  for (int trial = 0; trial < 20; ++trial) {
    const auto p = SomeParams(rng);
    const nlohmann::json eq = fossen::EquationsFor<JetForceModel>(p);
    const double x[6] = {0, 0, 0.3, u(rng), v(rng), r(rng)};
    const double in[4] = {f(rng), f(rng), 4 * f(rng), q(rng)};
    double dx[6];
    JetForceModel::Derivative<double>(x, in, p.data(), {}, dx);
    const std::map<std::string, double> channel = {
        {"u", x[3]},      {"v", x[4]},      {"r", x[5]},        {"tau_x", in[0]},
        {"tau_y", in[1]}, {"tau_n", in[2]}, {"jet_flow", in[3]}};
    for (int i = 0; i < 3; ++i) {
      const Expression e = Expression::Parse(eq.at(std::string("uvr").substr(i, 1)));
      std::vector<double> values;
      for (const std::string& name : e.Variables()) values.push_back(channel.at(name));
      EXPECT_NEAR(e.Evaluate(values), dx[3 + i], 1e-9 * (1 + std::abs(dx[3 + i]))) << i;
    }
  }
}

TEST(JetForceModelTest, ResistanceCoefficientIsPiecewiseLinearThroughItsKnots) {
  constexpr double h = JetForceModel::kKnotSpacing;
  constexpr int last = JetForceModel::kKnots - 1;
  std::array<double, JetForceModel::kParams> p{};
  for (int k = 0; k <= last; ++k) p[JetForceModel::kFirstKnot + k] = 10.0 + k * k;
  for (int k = 0; k <= last; ++k)
    EXPECT_NEAR(JetForceModel::Resistance(p.data(), h * k), 10.0 + k * k, 1e-12) << k;
  // Half-way between knots 3 and 4: the mean of theirs.
  EXPECT_NEAR(JetForceModel::Resistance(p.data(), 3.5 * h), 10.0 + (9 + 16) / 2.0, 1e-12);
  // Above the last knot it holds the last value.
  EXPECT_NEAR(JetForceModel::Resistance(p.data(), (last + 3) * h), 10.0 + last * last, 1e-12);
  // Its derivative through a Jet is the slope of the segment.
  using J = ceres::Jet<double, 1>;
  std::array<J, JetForceModel::kParams> pj;
  for (int i = 0; i < JetForceModel::kParams; ++i) pj[i] = J(p[i]);
  EXPECT_NEAR(JetForceModel::Resistance(pj.data(), J(3.25 * h, 0)).v[0], (16.0 - 9.0) / h, 1e-12);
}

// Issue 19's acceptance on one seed (the suite measures more): the hump and the lift-off are in
// c(U), so the planing rows hold too.
TEST(JetForceModelTest, FitOnJetForcesFreeRunsHeldOutRandomStepsAcrossRegimes) {
  Dataset train = testing::Simulate("odin-hs", "random-steps", 600, 0.005, 1);
  AddForces(train, "waterjet");
  PreprocessOptions pre;
  pre.rate_hz = 10.0;
  pre.step_breaks = false;  // as identify does on forces: the jet states slew, they do not step
  const std::vector<std::string> inputs(kWaterjetForceChannels.begin(),
                                        kWaterjetForceChannels.end());
  const PreparedData prep = Preprocess(train, {"u", "v", "r"}, inputs, pre);
  const fossen::FossenOptions o;
  const auto eq = fossen::FitEquationErrorFor<JetForceModel>(prep, o);
  const auto fit = fossen::FitSimulationErrorFor<JetForceModel>(prep, eq.params, o);
  // The shooting fit may stop at its iteration limit, creeping along a flat valley; it has then
  // long stopped changing what a free run shows.
  EXPECT_LT(fit.final_cost, 0.5 * fit.initial_cost) << fit.termination;
  const nlohmann::json model = {{"vessel", "odin-hs"},
                                {"states", {"u", "v", "r"}},
                                {"inputs", inputs},
                                {"preprocessing", {{"forces", "waterjet"}}},
                                {"equations", fossen::EquationsFor<JetForceModel>(fit.params)}};
  const Evaluation e =
      EvaluateModel(model, testing::Simulate("odin-hs", "random-steps", 600, 0.005, 1001));
  for (const char* c : {"u", "v", "r"})
    EXPECT_GE(e.metrics.at(c).at("fit_percent").get<double>(), 90.0) << c;
  const double rows = e.metrics.at("samples").get<double>();
  for (const auto& [regime, scores] : e.metrics.at("regimes").items()) {
    if (scores.at("samples").get<double>() <= 0.1 * rows) continue;
    double mean = 0.0;
    for (const char* c : {"u", "v", "r"}) mean += scores.at(c).at("fit_percent").get<double>() / 3;
    EXPECT_GE(mean, 80.0) << regime;
  }
  // Where the record runs (3-15 m/s), c(U) U^2 is the simulator's resistance R(U) to 10 %: the
  // hump at 5 m/s and the fall of R / U^2 to a sixth of its peak when planing, not told its form.
  for (double speed = 3.0; speed <= 15.0; speed += 1.0) {
    const double truth = OdinHs::Resistance(speed, OdinHs::kDefaultParams.data());
    EXPECT_NEAR(JetForceModel::Resistance(fit.params.data(), speed) * speed * speed, truth,
                0.1 * truth)
        << speed << " m/s";
  }
}

}  // namespace
}  // namespace usvid
