// GP-OLS's normal equations (methods/gp/ols.h), accumulated batch by batch as the search
// evaluates rows, equal [1 X]'[1 X], [1 X]'y and y'y of the whole matrix.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "methods/gp/ols.h"

namespace usvid::gp {
namespace {

TEST(GpNormalEquationsTest, AccumulatedInBatchesEqualsTheProductOfTheWholeMatrix) {
  constexpr int kRows = 700, kTerms = 4;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::MatrixXd x(kRows, kTerms);
  Eigen::VectorXd y(kRows);
  for (int i = 0; i < kRows; ++i) {
    for (int t = 0; t < kTerms; ++t) x(i, t) = n(rng);
    y(i) = n(rng);
  }
  NormalEquations eq(kTerms);
  for (int begin = 0; begin < kRows; begin += 256)
    eq.Add(x.middleRows(begin, std::min(256, kRows - begin)),
           y.segment(begin, std::min(256, kRows - begin)));

  Eigen::MatrixXd a(kRows, kTerms + 1);
  a << Eigen::VectorXd::Ones(kRows), x;
  const Eigen::MatrixXd gram = a.transpose() * a;
  const Eigen::MatrixXd lower = eq.gram.triangularView<Eigen::Lower>();
  EXPECT_LT((lower - Eigen::MatrixXd(gram.triangularView<Eigen::Lower>())).norm(),
            1e-10 * gram.norm());
  EXPECT_LT((eq.xty - a.transpose() * y).norm(), 1e-10 * eq.xty.norm());
  EXPECT_NEAR(eq.yty, y.squaredNorm(), 1e-10 * eq.yty);
  EXPECT_EQ(eq.rows, kRows);
}

}  // namespace
}  // namespace usvid::gp
