// Self-damping: the mean d(x')/dx of each equation on the data, the check behind model.json's
// "undamped" (a state whose equation neither damps nor restores it drifts in a free run).
#include "methods/self_damping.h"

#include <gtest/gtest.h>

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
}

}  // namespace
}  // namespace usvid
