// The number of GP-OLS terms chosen by held-out error over contiguous blocks
// (methods/gp/term_selection.h): a true term too small for the report's ERR threshold stays, a
// term that only fits noise goes, with no threshold set by hand.
#include <gtest/gtest.h>

#include <random>

#include "methods/gp/term_selection.h"

namespace usvid::gp {
namespace {

struct Rows {
  Eigen::MatrixXd x;  // columns: the terms
  Eigen::VectorXd y;
};

// y = 2 + 1.0 a + 0.15 b + noise (sd 0.05); c is noise that y does not depend on. b carries
// about 2 % of y's variance: under the report's threshold 0.05.
Rows Data(uint64_t seed) {
  constexpr int kRows = 4000;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  Rows d{Eigen::MatrixXd(kRows, 3), Eigen::VectorXd(kRows)};
  for (int i = 0; i < kRows; ++i) {
    const double a = std::sin(0.01 * i) + 0.3 * n(rng), b = n(rng), c = n(rng);
    d.x.row(i) << a, b, c;
    d.y(i) = 2.0 + 1.0 * a + 0.15 * b + 0.05 * n(rng);
  }
  return d;
}

std::vector<NormalEquations> Blocks(const Rows& d) {
  std::vector<NormalEquations> blocks;
  const long rows = d.y.size();
  for (int b = 0; b < kHeldOutBlocks; ++b) {
    const long begin = b * rows / kHeldOutBlocks, end = (b + 1) * rows / kHeldOutBlocks;
    blocks.emplace_back(3);
    blocks.back().Add(d.x.middleRows(begin, end - begin), d.y.segment(begin, end - begin));
  }
  return blocks;
}

TEST(GpTermSelectionTest, KeepsASmallTrueTermAndDropsNoiseWithoutAThreshold) {
  int exact = 0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    const Rows d = Data(seed);
    const OlsFit fit = FitOlsHeldOut(Blocks(d));
    ASSERT_TRUE(fit.valid);
    exact += fit.kept == std::vector<int>{0, 1};
    if (fit.kept == std::vector<int>{0, 1}) {
      EXPECT_NEAR(fit.weights[0], 1.0, 0.01);
      EXPECT_NEAR(fit.weights[1], 0.15, 0.01);
      EXPECT_NEAR(fit.bias, 2.0, 0.01);
    }
    EXPECT_LE(fit.r2_heldout, fit.r2);
  }
  EXPECT_GE(exact, 9);  // a pure-noise term helps held-out error by chance now and then
  // The report's threshold cuts the small true term.
  NormalEquations all(3);
  all.Add(Data(1).x, Data(1).y);
  EXPECT_EQ(FitOls(all, 0.05).kept, std::vector<int>{0});
}

// Degenerate data (a constant target) give an invalid fit, not a NaN.
TEST(GpTermSelectionTest, ConstantTargetIsInvalid) {
  Rows d = Data(1);
  d.y.setConstant(3.0);
  EXPECT_FALSE(FitOlsHeldOut(Blocks(d)).valid);
}

}  // namespace
}  // namespace usvid::gp
