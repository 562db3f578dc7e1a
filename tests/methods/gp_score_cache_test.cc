// The GP search's score cache (methods/gp/score_cache.h) and the normal equations it saves
// recomputing (methods/gp/ols.h): a tree bred again takes its first score, a different tree
// does not, old entries go, and the column-by-column Gram matrix equals [1 X]'[1 X].
#include <gtest/gtest.h>

#include <random>

#include "methods/gp/ols.h"
#include "methods/gp/score_cache.h"
#include "methods/gp/search.h"

namespace usvid::gp {
namespace {

// c * x0, in postfix order (children before their parent).
Tree Scaled(double c) {
  Tree t(3);
  t[0].op = Op::kConst;
  t[0].value = c;
  t[1].op = Op::kVar;
  t[1].var = 0;
  t[2].op = Op::kMul;
  UpdateLengths(t);
  return t;
}

Model Scored(double fitness) {
  Model m;
  m.fitness = fitness;
  return m;
}

TEST(GpScoreCacheTest, ATreeBredAgainTakesItsFirstScore) {
  ScoreCache cache(3);
  cache.Insert(Scaled(2.0), Scored(0.5), 0);
  const Model* found = cache.Find(Scaled(2.0), 1);
  ASSERT_NE(found, nullptr);
  EXPECT_EQ(found->fitness, 0.5);
  EXPECT_EQ(cache.Find(Scaled(3.0), 1), nullptr);
  // Constants compare by their bits: -0 * x0 is another tree than 0 * x0.
  cache.Insert(Scaled(0.0), Scored(0.1), 1);
  EXPECT_EQ(cache.Find(Scaled(-0.0), 1), nullptr);
}

TEST(GpScoreCacheTest, ForgetsTreesNotBredWithinTheKeptGenerations) {
  ScoreCache cache(2);
  cache.Insert(Scaled(1.0), Scored(0.1), 0);
  cache.Insert(Scaled(2.0), Scored(0.2), 0);
  ASSERT_NE(cache.Find(Scaled(2.0), 2), nullptr);  // bred again in generation 2
  cache.Forget(3);                                 // keeps what was bred in 1..3
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_EQ(cache.Find(Scaled(1.0), 3), nullptr);
  EXPECT_NE(cache.Find(Scaled(2.0), 3), nullptr);
}

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
