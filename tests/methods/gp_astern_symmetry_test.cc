// Astern symmetry (methods/gp/astern_symmetry.h): a hull's yaw damping written as a product with
// u turns into growth astern; written with |u| it damps both ways, and ahead nothing changes.
#include <gtest/gtest.h>

#include "methods/gp/astern_symmetry.h"
#include "methods/gp/search.h"

namespace usvid::gp {
namespace {

const std::vector<std::string> kNames = {"u", "r", "delta"};
constexpr int kU = 0, kR = 1;

Node Var(uint16_t i) { return {Op::kVar, i, 1, 0.0}; }
Node Binary(Op op) { return {op, 0, 1, 0.0}; }

// r' = w1 u*r + w2 u*delta: a yaw damping that rides on u, and the rudder's moment.
Tree YawEquation() {
  Tree t = {Var(kU), Var(kR),          Binary(Op::kMul), Var(kU),
            Var(2),  Binary(Op::kMul), Binary(Op::kAdd)};
  UpdateLengths(t);
  return t;
}

// d(r')/dr of w * term at (u, r), by central differences.
double Slope(const Tree& tree, double w, double u, double r) {
  Model m;
  m.tree = tree;
  m.term_roots = {static_cast<int>(tree.size()) - 1};
  m.weights = {w};
  std::vector<Eigen::VectorXd> at(3, Eigen::VectorXd::Constant(1, 0.1));
  at[kU](0) = u;
  at[kR](0) = r + 1e-6;
  const double up = Predict(m, at)(0);
  at[kR](0) = r - 1e-6;
  return (up - Predict(m, at)(0)) / 2e-6;
}

TEST(GpAsternSymmetryTest, WritesTheDampingTermWithAbsAndLeavesTheRudderTerm) {
  const Tree t = AsternSymmetric(YawEquation(), kU, kR);
  EXPECT_EQ(ToString(t, kNames), "((abs(u) * r) + (u * delta))");
}

TEST(GpAsternSymmetryTest, DampsAsternWhereTheProductWithUDrives) {
  Tree ur = {Var(kU), Var(kR), Binary(Op::kMul)};
  UpdateLengths(ur);
  const Tree abs_ur = AsternSymmetric(ur, kU, kR);
  // Ahead the two are the same term: N_r r |U| with N_r < 0.
  EXPECT_DOUBLE_EQ(Slope(ur, -0.37, 0.3, 0.01), Slope(abs_ur, -0.37, 0.3, 0.01));
  // Astern, u*r drives the yaw rate; |u|*r still damps it.
  EXPECT_GT(Slope(ur, -0.37, -0.1, 0.01), 0.0);
  EXPECT_LT(Slope(abs_ur, -0.37, -0.1, 0.01), 0.0);
}

TEST(GpAsternSymmetryTest, LeavesWrappedTermsAndTheSurgeEquationAlone) {
  Tree wrapped = {Var(kU), {Op::kAbs, 0, 1, 0.0}, Var(kR), Binary(Op::kMul)};
  UpdateLengths(wrapped);
  EXPECT_EQ(ToString(AsternSymmetric(wrapped, kU, kR), kNames), "(abs(u) * r)");
  // u' = w u*r: the surge equation's own state is u, whose sign a term u*|u| already carries.
  EXPECT_EQ(ToString(AsternSymmetric(YawEquation(), kU, kU), kNames),
            ToString(YawEquation(), kNames));
}

}  // namespace
}  // namespace usvid::gp
