// Regime features (methods/regime_features.h): the Froude number Fn = U / sqrt(g L) and hinges
// abs(Fn - k) at quantiles of the record's Fn are offered when the record crosses a regime
// boundary (Fn 0.4 or 1.1) and the hull has a length; GP-SR searches them like variables (SINDy
// takes them as library columns), writes them into the equations as expressions in u and v, and
// recomputes them from the simulated states when it simulates candidates (model_selection.h).
#include "methods/regime_features.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <cmath>

#include "core/error.h"
#include "core/expression.h"
#include "methods/gp/model_selection.h"
#include "simulators/odin_hs.h"

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
  const auto f = RegimeFeatures("froude", kFroudePerSpeed, Speeds(3.0, 4.0), kSindyFroudeHinges);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].name, "Fn");
  const Expression e = Expression::Parse(f[0].expression);
  const double uv[2] = {12.0, 0.5};  // Variables() order: u, v
  ASSERT_EQ(e.Variables(), (std::vector<std::string>{"u", "v"}));
  EXPECT_NEAR(e.Evaluate(uv), std::hypot(12.0, 0.5) / std::sqrt(9.81 * kLength), 1e-9);
}

// Fn 0.2 .. 1.6, evenly in time: the hinges sit at its 1/9 .. 8/9 quantiles (the samples at or
// just below 0.2 + 1.4 i / 9, rounded to 0.01), and each evaluates to abs(Fn - k).
TEST(RegimeFeaturesTest, HingesSitAtQuantilesOfTheRecordsFroudeNumber) {
  const double root_gl = std::sqrt(9.81 * kLength);  // speed at Fn 1 [m/s]
  // Sway 0.1 m/s shifts Fn by at most 0.1^2 / (2 u sqrt(gL)) < 0.001: the knots round as in u.
  const auto f = RegimeFeatures("hinges", kFroudePerSpeed, Speeds(0.2 * root_gl, 1.6 * root_gl),
                                kSindyFroudeHinges);
  ASSERT_EQ(f.size(), 1u + kSindyFroudeHinges);
  EXPECT_EQ(f[0].name, "Fn");
  const double knots[] = {0.35, 0.51, 0.66, 0.82, 0.97, 1.12, 1.28, 1.43};
  ASSERT_EQ(std::size(knots), static_cast<size_t>(kSindyFroudeHinges));
  for (int i = 0; i < kSindyFroudeHinges; ++i) {
    EXPECT_EQ(f[i + 1].name, "Fn_k" + std::to_string(i + 1));
    const Expression e = Expression::Parse(f[i + 1].expression);
    const double uv[2] = {12.0, 0.5};
    EXPECT_NEAR(e.Evaluate(uv), std::abs(std::hypot(12.0, 0.5) / root_gl - knots[i]), 1e-9)
        << f[i + 1].expression;
  }
  // A record at one speed has one knot, not eight equal ones.
  EXPECT_EQ(RegimeFeatures("hinges", kFroudePerSpeed, Speeds(5.0, 5.0), kSindyFroudeHinges).size(),
            2u);
}

// Why hinges: odin-hs's resistance (simulators/odin_hs.h) rises about as U^6 to the hump at
// Fn 0.5 and levels off as lift takes over. Least squares on [1, Fn, hinges at the quantiles of
// a 3-17 m/s record] follows it to within 8 % of its largest value at every speed (4.0 %); on
// [1, Fn, Fn^2], the form a search builds without hinges, the worst error is 2.5 times that or
// more (20.5 %).
TEST(RegimeFeaturesTest, HingesFollowTheResistanceHumpAQuadraticMisses) {
  const Dataset record = Speeds(3.0, 17.0);
  const auto f = RegimeFeatures("hinges", kFroudePerSpeed, record, kSindyFroudeHinges);
  const int n = 141;
  Eigen::VectorXd resistance(n);
  Eigen::MatrixXd hinges(n, f.size() + 1), quadratic(n, 3);
  for (int k = 0; k < n; ++k) {
    const double speed = 3.0 + 0.1 * k, fn = speed * kFroudePerSpeed;
    resistance(k) = OdinHs::Resistance(speed, OdinHs::kDefaultParams.data());
    const double uv[2] = {speed, 0.0};
    hinges(k, 0) = 1.0;
    for (size_t i = 0; i < f.size(); ++i)
      hinges(k, i + 1) = Expression::Parse(f[i].expression).Evaluate(uv);
    quadratic.row(k) << 1.0, fn, fn * fn;
  }
  auto worst = [&](const Eigen::MatrixXd& a) {
    const Eigen::VectorXd w = a.colPivHouseholderQr().solve(resistance);
    return (a * w - resistance).cwiseAbs().maxCoeff() / resistance.maxCoeff();
  };
  EXPECT_LT(worst(hinges), 0.08);
  EXPECT_GT(worst(quadratic), 2.5 * worst(hinges));
}

TEST(RegimeFeaturesTest, AutoOffersHingesOnlyWhenTheRecordCrossesARegimeBoundary) {
  const double fn = std::sqrt(9.81 * kLength);  // speed at Fn 1 [m/s]
  EXPECT_TRUE(
      RegimeFeatures("auto", kFroudePerSpeed, Speeds(0.2 * fn, 0.35 * fn), kSindyFroudeHinges)
          .empty());  // displ.
  EXPECT_TRUE(
      RegimeFeatures("auto", kFroudePerSpeed, Speeds(0.5 * fn, 1.0 * fn), kSindyFroudeHinges)
          .empty());  // semi
  for (const auto& [from, to] : {std::pair{0.3, 0.6}, std::pair{0.9, 1.5}}) {
    const auto a =
        RegimeFeatures("auto", kFroudePerSpeed, Speeds(from * fn, to * fn), kSindyFroudeHinges);
    const auto h =
        RegimeFeatures("hinges", kFroudePerSpeed, Speeds(from * fn, to * fn), kSindyFroudeHinges);
    ASSERT_EQ(a.size(), 1u + kSindyFroudeHinges) << from;
    for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].expression, h[i].expression);
  }
  EXPECT_TRUE(RegimeFeatures("auto", 0.0, Speeds(0.3 * fn, 1.5 * fn), kSindyFroudeHinges)
                  .empty());  // no length
  EXPECT_TRUE(
      RegimeFeatures("none", kFroudePerSpeed, Speeds(0.3 * fn, 1.5 * fn), kSindyFroudeHinges)
          .empty());
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
  EXPECT_THAT(
      message([] { RegimeFeatures("speed", kFroudePerSpeed, Speeds(1, 2), kSindyFroudeHinges); }),
      HasSubstr("unknown"));
  EXPECT_THAT(message([] { RegimeFeatures("froude", 0.0, Speeds(1, 2), kSindyFroudeHinges); }),
              HasSubstr("no hull length"));
  Dataset no_v;
  no_v.SetTime(Eigen::VectorXd::LinSpaced(5, 0, 1));
  no_v.Set("u", Eigen::VectorXd::Ones(5));
  EXPECT_THAT(message([&] { RegimeFeatures("froude", kFroudePerSpeed, no_v, kSindyFroudeHinges); }),
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
