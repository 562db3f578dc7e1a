// GP-SR on data that make trees overflow (issue 11): values near 1e150 multiply to infinity in
// float and double, exp of them overflows, a division by a near-zero column explodes. Every
// fitness the search records stays finite, the model it returns is finite, and the search ends.
#include <gtest/gtest.h>

#include <cmath>

#include "methods/gp/search.h"

namespace usvid::gp {
namespace {

TEST(GpDivergenceTest, FitnessStaysFiniteWhenTreesOverflow) {
  constexpr long kRows = 400;
  GpProblem p;
  p.names = {"big", "tiny", "x"};
  Eigen::VectorXd big(kRows), tiny(kRows), x(kRows);
  for (long k = 0; k < kRows; ++k) {
    big(k) = 1e150 * (1.0 + 0.001 * k);
    tiny(k) = k % 2 == 0 ? 0.0 : 1e-300;
    x(k) = std::sin(0.05 * k);
  }
  p.variables = {big, tiny, x};
  p.target = (2.0 * x.array() + 0.5).matrix();
  GpOptions o;
  o.functions = {Op::kAdd, Op::kSub, Op::kMul, Op::kDiv, Op::kExp};
  o.population = 200;
  o.generations = 8;
  o.stagnation = 100;
  o.threads = 1;
  std::vector<GenerationLog> logs;
  const GpResult r = RunGp(p, o, [&](const GenerationLog& g) { logs.push_back(g); });
  ASSERT_FALSE(logs.empty());
  for (const GenerationLog& g : logs) {
    EXPECT_TRUE(std::isfinite(g.best_fitness)) << g.generation;
    EXPECT_TRUE(std::isfinite(g.best_r2)) << g.generation;
  }
  EXPECT_TRUE(std::isfinite(r.best.fitness));
  const Eigen::VectorXd prediction = Predict(r.best, p.variables);
  EXPECT_TRUE(prediction.allFinite());
  EXPECT_GT(r.best.r2, 0.9);  // and it still finds 2 x + 0.5 among the overflowing trees
}

}  // namespace
}  // namespace usvid::gp
