// Self-damping: the mean d(x')/dx of each equation on the data, and the same at straight running,
// the checks behind model.json's "undamped" (a state whose equation neither damps nor restores it
// drifts in a free run).
#include "methods/self_damping.h"

#include <gtest/gtest.h>

#include <cmath>

#include "methods/identify.h"
#include "tests/support/synthetic_data.h"

namespace usvid {
namespace {

Dataset Record() {
  Dataset d(Eigen::VectorXd::LinSpaced(200, 0.0, 19.9));
  d.Set("u", Eigen::VectorXd::LinSpaced(200, 0.5, 2.5));
  d.Set("r", Eigen::VectorXd::LinSpaced(200, -0.1, 0.1));
  d.Set("tau", Eigen::VectorXd::Ones(200));
  return d;
}

// Linear damping gives its coefficient; quadratic damping its mean slope -2 c |u|; an equation
// without its state, or one that grows with it, is not damped.
TEST(SelfDampingTest, MeanSlopeOfEachEquationInItsOwnState) {
  const auto d = SelfDamping(
      {{"u", "-0.5*u + 2*tau - 0.1*abs(u)*u"}, {"r", "0.3*tau"}, {"psi", "r"}}, Record());
  EXPECT_NEAR(d.at("u"), -0.5 - 0.2 * 1.5, 1e-6);  // the mean of |u| is 1.5
  EXPECT_EQ(d.at("r"), 0.0);
  EXPECT_FALSE(d.contains("psi"));  // no channel psi: nothing to say
  EXPECT_GT(SelfDamping({{"u", "0.1*u*u"}}, Record()).at("u"), 0.0);
  EXPECT_TRUE(SelfDamping({{"u", "-u + gust"}}, Record()).empty());  // a variable the data lack
}

// A zig-zag's record: the sway velocity swings through zero, the speed stays near 7 m/s.
Dataset Zigzag() {
  const int n = 600;
  Dataset d(Eigen::VectorXd::LinSpaced(n, 0.0, 599.0));
  Eigen::VectorXd v(n), u(n), delta(n);
  for (int i = 0; i < n; ++i) {
    v(i) = 0.4 * std::sin(2 * M_PI * i / 120.0);
    u(i) = 7.0 - 0.5 * std::abs(v(i));
    delta(i) = v(i) > 0 ? -0.35 : 0.35;
  }
  d.Set("u", u);
  d.Set("v", v);
  d.Set("delta", delta);
  return d;
}

// u' = c - k |v u| damps the surge on average over the zig-zag (-k mean|v|), but running straight
// (v = 0) not at all: its speed grows without bound. Read at straight running, its damping is 0,
// and a surge damped by its own speed keeps its coefficient there. Sway damping that grows with
// the motion (|v| v) is read at the sway's RMS, where it is below 0, not at v = 0.
TEST(SelfDampingTest, StraightRunningFindsADampingThatOnlyTheLateralMotionGives) {
  const Dataset d = Zigzag();
  const EquationList drifting = {{"u", "0.006 - 0.0025*abs(v*u)"}};
  EXPECT_LT(SelfDamping(drifting, d).at("u"), -1e-4);
  EXPECT_EQ(StraightRunningDamping(drifting, d).at("u"), 0.0);
  const EquationList damped = {{"u", "0.006 - 0.001*u - 0.0025*abs(v*u)"},
                               {"v", "-0.3*abs(v)*v + 0.01*delta"}};
  const auto straight = StraightRunningDamping(damped, d);
  EXPECT_NEAR(straight.at("u"), -0.001, 1e-9);
  const double v_rms = std::sqrt(d["v"].squaredNorm() / 600.0);
  EXPECT_NEAR(straight.at("v"), -0.6 * v_rms, 1e-6);  // d(-0.3 |v| v)/dv = -0.6 |v|
}

// Identify writes the check into model.json for any method with equations: here lti on odin3dof
// random steps, whose surge the hull damps.
TEST(SelfDampingTest, IdentifyReportsUndampedStates) {
  Dataset d = testing::Simulate("odin3dof", "random-steps", 300, 0.005, 3);
  IdentifyRequest request;
  request.method = "lti";
  request.states = {"u", "v", "r"};
  request.inputs = {"tau_x", "tau_y", "tau_n"};
  const nlohmann::json model = Identify(d, request);
  ASSERT_TRUE(model.contains("self_damping"));
  for (const std::string s : {"u", "v", "r"}) EXPECT_TRUE(model["self_damping"].contains(s)) << s;
  EXPECT_LT(model["self_damping"]["u"].get<double>(), 0.0);  // odin3dof's surge is damped
  EXPECT_TRUE(model["undamped"].is_array());
  ASSERT_TRUE(model.contains("self_damping_straight_running"));
  EXPECT_LT(model["self_damping_straight_running"]["u"].get<double>(), 0.0);
}

}  // namespace
}  // namespace usvid
