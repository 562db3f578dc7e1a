// Regime features (methods/regime_features.h): the Froude number Fn = U / sqrt(g L) is offered
// when the record crosses a regime boundary (Fn 0.4 or 1.1) and the hull has a length; GP-SR
// searches it like a variable, writes it into the equations as its expression in u and v, and
// recomputes it from the simulated states when it simulates candidates (model_selection.h).
#include "methods/regime_features.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "methods/expression.h"
#include "methods/gp/model_selection.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;

constexpr double kLength = 10.5;                                 // odin-hs's waterline [m]
const double kFroudePerSpeed = 1.0 / std::sqrt(9.81 * kLength);  // [s/m]

// A record of surge speed `u0` to `u1` (linear in time), sway 0.1 m/s.
Dataset Speeds(double u0, double u1) {
  Dataset d;
  const int n = 101;
  Eigen::VectorXd t(n), u(n), v = Eigen::VectorXd::Constant(n, 0.1);
  for (int k = 0; k < n; ++k) t(k) = 0.1 * k, u(k) = u0 + (u1 - u0) * k / (n - 1.0);
  d.SetTime(t);
  d.Set("u", u);
  d.Set("v", v);
  return d;
}

TEST(RegimeFeaturesTest, FroudeNumberIsSpeedOverRootGL) {
  const auto f = RegimeFeatures("froude", kFroudePerSpeed, Speeds(3.0, 4.0));
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].name, "Fn");
  const Expression e = Expression::Parse(f[0].expression);
  const double uv[2] = {12.0, 0.5};  // Variables() order: u, v
  ASSERT_EQ(e.Variables(), (std::vector<std::string>{"u", "v"}));
  EXPECT_NEAR(e.Evaluate(uv), std::hypot(12.0, 0.5) / std::sqrt(9.81 * kLength), 1e-9);
}

TEST(RegimeFeaturesTest, AutoOffersItOnlyWhenTheRecordCrossesARegimeBoundary) {
  const double fn = std::sqrt(9.81 * kLength);  // speed at Fn 1 [m/s]
  EXPECT_TRUE(
      RegimeFeatures("auto", kFroudePerSpeed, Speeds(0.2 * fn, 0.35 * fn)).empty());  // displ.
  EXPECT_TRUE(RegimeFeatures("auto", kFroudePerSpeed, Speeds(0.5 * fn, 1.0 * fn)).empty());  // semi
  EXPECT_EQ(RegimeFeatures("auto", kFroudePerSpeed, Speeds(0.3 * fn, 0.6 * fn)).size(), 1u);
  EXPECT_EQ(RegimeFeatures("auto", kFroudePerSpeed, Speeds(0.9 * fn, 1.5 * fn)).size(), 1u);
  EXPECT_TRUE(RegimeFeatures("auto", 0.0, Speeds(0.3 * fn, 1.5 * fn)).empty());  // no length
  EXPECT_TRUE(RegimeFeatures("none", kFroudePerSpeed, Speeds(0.3 * fn, 1.5 * fn)).empty());
}

TEST(RegimeFeaturesTest, RefusesUnknownSpecsAndFroudeWithoutLengthOrSpeeds) {
  auto message = [](auto&& call) {
    try {
      call();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message([] { RegimeFeatures("speed", kFroudePerSpeed, Speeds(1, 2)); }),
              HasSubstr("unknown"));
  EXPECT_THAT(message([] { RegimeFeatures("froude", 0.0, Speeds(1, 2)); }),
              HasSubstr("no hull length"));
  Dataset no_v;
  no_v.SetTime(Eigen::VectorXd::LinSpaced(5, 0, 1));
  no_v.Set("u", Eigen::VectorXd::Ones(5));
  EXPECT_THAT(message([&] { RegimeFeatures("froude", kFroudePerSpeed, no_v); }),
              HasSubstr("u and v"));
}

// Model selection simulates a candidate with the feature recomputed from the simulated state:
// u' = -F with F = 2 u (a derived column) decays as exp(-2 t), which the candidate matches
// exactly only when F follows the simulated u; a stale, measured F would leave an error.
TEST(RegimeFeaturesTest, SelectionRecomputesDerivedColumnsFromTheSimulatedStates) {
  const int n = 401;
  const double h = 0.01;
  Eigen::VectorXd t(n), u(n);
  for (int k = 0; k < n; ++k) t(k) = h * k, u(k) = std::exp(-2.0 * h * k);
  gp::SelectionData data;
  data.t = t;
  data.names = {"u", "(2*u)"};
  data.variables = {u, Eigen::VectorXd::Zero(n)};  // the measured feature is wrong on purpose
  data.validation_begin = 0;
  data.horizon_s = 1.0;
  data.derived.push_back({1, Expression::Parse("2*u"), {0}});
  gp::Model m;
  m.tree = {gp::Node{gp::Op::kVar, 1, 1, 0.0}};
  m.term_roots = {0};
  m.weights = {-1.0};
  const gp::Selection s = gp::SelectModels(data, {{"u", {m}}});
  ASSERT_EQ(s.scores.size(), 1u);
  EXPECT_LT(s.scores[0], 1e-8);  // RK4 on exp(-2t) at h = 0.01
}

}  // namespace
}  // namespace usvid
