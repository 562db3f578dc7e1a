// Term completion (methods/gp/term_completion.h): a candidate that lacks a term the data
// support, small in the derivative's variance, gets it back from the library; a library term
// that only fits noise is not kept; no product is offered to a search without '*'.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "methods/gp/ols.h"
#include "methods/gp/term_completion.h"

namespace usvid::gp {
namespace {

// Variables u, v, r, tau, z. The target is a surge equation in which the sway-yaw coupling v*r
// carries about 2 % of the variance: y = 0.0002 tau - 0.3 u + 1.4 v r + noise. z is unrelated.
GpProblem Surge(uint64_t seed) {
  constexpr int kRows = 6000;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  GpProblem p;
  p.names = {"u", "v", "r", "tau", "z"};
  p.variables.assign(5, Eigen::VectorXd(kRows));
  p.target.resize(kRows);
  for (int i = 0; i < kRows; ++i) {
    const double t = 0.05 * i;
    const double u = 5.0 + 3.0 * std::sin(0.01 * t) + 0.3 * n(rng);
    const double r = 0.15 * std::sin(0.2 * t), v = -3.0 * r + 0.3 * n(rng);
    const double tau = 1500.0 * u + 2000.0 * n(rng);
    p.variables[0](i) = u;
    p.variables[1](i) = v;
    p.variables[2](i) = r;
    p.variables[3](i) = tau;
    p.variables[4](i) = n(rng);
    p.target(i) = 0.0002 * tau - 0.3 * u + 1.4 * v * r + 0.01 * n(rng);
  }
  return p;
}

// The candidate the search found: bias + w1 tau + w2 u, without v*r.
Model Candidate(const GpProblem& p, const GpOptions& o) {
  const Tree tree = {{Op::kVar, 3, 1, 0.0}, {Op::kVar, 0, 1, 0.0}, {Op::kAdd, 0, 3, 0.0}};
  return FitTree(tree, p, o);
}

TEST(GpTermCompletionTest, LibraryHoldsFeaturesThenProductsOfTwoStates) {
  const std::vector<Tree> library = CompletionLibrary({0, 1, 2}, {4}, {Op::kAdd, Op::kMul});
  ASSERT_EQ(library.size(), 1u + 6u);  // z, then uu uv ur vv vr rr
  const std::vector<std::string> names = {"u", "v", "r", "tau", "z"};
  EXPECT_EQ(ToString(library[0], names), "z");
  EXPECT_EQ(ToString(library[5], names), "(v * r)");
  // Without '*' the search could not write a product, and completion offers none.
  EXPECT_EQ(CompletionLibrary({0, 1, 2}, {4}, {Op::kAdd, Op::kSub}).size(), 1u);
}

TEST(GpTermCompletionTest, RestoresASmallTrueTermAndLeavesNoiseOut) {
  const GpOptions o;
  int restored = 0;
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    const GpProblem p = Surge(seed);
    const Model before = Candidate(p, o);
    const Model after = CompleteTerms(before, CompletionLibrary({0, 1, 2}, {4}, o.functions), p, o);
    EXPECT_GT(after.r2_heldout, before.r2_heldout);
    const std::string equation = after.Equation(p.names);
    EXPECT_EQ(equation.find("z"), std::string::npos) << equation;
    bool has_vr = false;
    for (size_t t = 0; t < after.term_roots.size(); ++t) {
      const int root = after.term_roots[t];
      const Tree term(after.tree.begin() + root + 1 - after.tree[root].length,
                      after.tree.begin() + root + 1);
      if (ToString(term, p.names) == "(v * r)") {
        has_vr = true;
        EXPECT_NEAR(after.weights[t], 1.4, 0.05) << equation;
      }
    }
    restored += has_vr;
  }
  EXPECT_EQ(restored, 5);
}

}  // namespace
}  // namespace usvid::gp
