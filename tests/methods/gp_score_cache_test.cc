// The GP search's score cache (methods/gp/score_cache.h): a tree bred again takes its first
// score, a different tree does not, and trees not bred again within the kept generations go.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace usvid::gp
