// The refit of a chosen candidate (methods/gp/search.h, FitTerms): every term stays, weighted
// by least squares on all rows, where the search's scoring (FitTree) selects terms again by
// held-out error and may cut one. GP chooses a candidate by how it simulates
// (model_selection.h); a refit that cut a term would write another model than the one chosen.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "methods/gp/ols.h"
#include "methods/gp/search.h"

namespace usvid::gp {
namespace {

// y = 0.3 + a + 0.015 b + noise of standard deviation 1, over 6000 rows: b's weight is about
// one standard error (1/sqrt(6000) = 0.013), so the held-out one-standard-error rule cuts it.
GpProblem WeakTerm() {
  constexpr int kRows = 6000;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n(0.0, 1.0);
  GpProblem p;
  p.names = {"a", "b"};
  p.variables.assign(2, Eigen::VectorXd(kRows));
  p.target.resize(kRows);
  for (int i = 0; i < kRows; ++i) {
    p.variables[0](i) = n(rng);
    p.variables[1](i) = n(rng);
    p.target(i) = 0.3 + p.variables[0](i) + 0.015 * p.variables[1](i) + n(rng);
  }
  return p;
}

TEST(GpFitTermsTest, KeepsATermThatTheHeldOutSelectionCutsAndWeighsItByLeastSquares) {
  const GpProblem p = WeakTerm();
  const Tree a_plus_b = {{Op::kVar, 0, 1, 0.0}, {Op::kVar, 1, 1, 0.0}, {Op::kAdd, 0, 3, 0.0}};
  // The premise: scored as the search scores, b is cut.
  ASSERT_EQ(FitTree(a_plus_b, p, GpOptions{}).weights.size(), 1u);

  const Model m = FitTerms(a_plus_b, p);
  ASSERT_EQ(m.weights.size(), 2u);
  Eigen::MatrixXd x(p.target.size(), 3);
  x << Eigen::VectorXd::Ones(p.target.size()), p.variables[0], p.variables[1];
  const Eigen::VectorXd w = x.colPivHouseholderQr().solve(p.target);
  EXPECT_NEAR(m.bias, w(0), 1e-9);
  EXPECT_NEAR(m.weights[0], w(1), 1e-9);
  EXPECT_NEAR(m.weights[1], w(2), 1e-9);
}

TEST(GpFitTermsTest, ATermThatRepeatsAnotherIsStillLeftOut) {
  GpProblem p = WeakTerm();
  p.variables[1] = 2.0 * p.variables[0];  // b = 2 a: no weight of its own can be fitted
  const Tree a_plus_b = {{Op::kVar, 0, 1, 0.0}, {Op::kVar, 1, 1, 0.0}, {Op::kAdd, 0, 3, 0.0}};
  const Model m = FitTerms(a_plus_b, p);
  ASSERT_EQ(m.weights.size(), 1u);
  EXPECT_NEAR(m.weights[0], 1.0, 0.05);
}

}  // namespace
}  // namespace usvid::gp
