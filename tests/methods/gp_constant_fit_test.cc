// Constant optimisation (methods/gp/constant_fit.h): Levenberg-Marquardt through the tree moves
// a constant inside a nonlinear function, which OLS cannot, and leaves pure scale factors alone.
#include <gtest/gtest.h>

#include <cmath>

#include "methods/gp/constant_fit.h"

namespace usvid::gp {
namespace {

// abs(x - c) as a postfix tree.
Tree AbsOfXMinus(double c) {
  Tree t = {
      {Op::kVar, 0, 1, 0.0}, {Op::kConst, 0, 1, c}, {Op::kSub, 0, 1, 0.0}, {Op::kAbs, 0, 1, 0.0}};
  UpdateLengths(t);
  return t;
}

TEST(GpConstantFitTest, MovesTheConstantInsideAbs) {
  // y = 0.5 + 2 |x - 0.7| on x in [-2, 2]; the tree starts at c = 0.2.
  std::vector<double> x, y;
  for (int i = 0; i < 400; ++i) {
    x.push_back(-2.0 + 4.0 * i / 399.0);
    y.push_back(0.5 + 2.0 * std::abs(x.back() - 0.7));
  }
  Model m;
  m.tree = AbsOfXMinus(0.2);
  m.term_roots = {3};
  m.weights = {1.5};
  m.bias = 0.9;
  ASSERT_TRUE(HasTunableConstants(m));
  const ConstantFitResult r = FitConstants(m, {x.data()}, y.data(), 400, 20);
  ASSERT_TRUE(r.improved);
  EXPECT_NEAR(r.tree[1].value, 0.7, 1e-6);
  EXPECT_LT(r.final_cost, 1e-10);
}

TEST(GpConstantFitTest, ScaleFactorsAreNotTuned) {
  Tree t = {{Op::kConst, 0, 1, 0.3}, {Op::kVar, 0, 1, 0.0}, {Op::kMul, 0, 1, 0.0}};
  UpdateLengths(t);
  Model m;
  m.tree = t;
  m.term_roots = {2};
  m.weights = {1.0};
  EXPECT_FALSE(HasTunableConstants(m));
}

}  // namespace
}  // namespace usvid::gp
