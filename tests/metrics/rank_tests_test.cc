// Rank statistics for `usvid compare`, checked against values computed independently with
// Python 3 and numpy 1.24 (no scipy): quantiles against numpy.percentile; exact Wilcoxon p-values
// by enumerating all 2^n sign patterns over average ranks counted directly; the normal
// approximation from its closed formula; chi-square survival against textbook critical values and
// the closed forms for 1 and 2 degrees of freedom; Friedman against a hand computation and, with
// ties, against the tie-corrected formula (for 3 treatments p = exp(-Q/2) exactly); Holm by hand.
// Bad input (NaN, mismatched sizes) is refused.
#include "metrics/rank_tests.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"

namespace usvid {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Type 7 on an unsorted sample with repeats: numpy.percentile(q, 100 p) to the last bit or two.
TEST(RankTestsTest, QuantileMatchesNumpyPercentile) {
  const std::vector<double> q = {3.5, -1.0, 2.0, 2.0, 7.25, 0.0, 10.0, 2.0, -4.5};
  const std::vector<std::pair<double, double>> expected = {{0.0, -4.5}, {0.1, -1.7}, {0.25, 0.0},
                                                           {0.5, 2.0},  {0.6, 2.0},  {0.75, 3.5},
                                                           {0.9, 7.8},  {1.0, 10.0}};
  for (const auto& [p, value] : expected) EXPECT_NEAR(Quantile(q, p), value, 1e-12) << "p=" << p;
  EXPECT_DOUBLE_EQ(Median(q), 2.0);
  const Spread s = Describe(q);
  EXPECT_EQ(s.n, 9);
  EXPECT_DOUBLE_EQ(s.median, 2.0);
  EXPECT_DOUBLE_EQ(s.q1, 0.0);
  EXPECT_DOUBLE_EQ(s.q3, 3.5);
}

// Infinities sort to the ends; interpolating towards one gives it (as R), only -inf to +inf is
// undefined; an empty sample has no quantile.
TEST(RankTestsTest, QuantileWithInfinitiesAndEmpty) {
  const std::vector<double> v = {3.0, -kInf, 1.0, kInf, 2.0};  // sorted: -inf 1 2 3 inf
  EXPECT_EQ(Quantile(v, 0.0), -kInf);
  EXPECT_EQ(Quantile(v, 0.1), -kInf);
  EXPECT_DOUBLE_EQ(Quantile(v, 0.25), 1.0);
  EXPECT_DOUBLE_EQ(Median(v), 2.0);
  EXPECT_DOUBLE_EQ(Quantile(v, 0.625), 2.5);
  EXPECT_EQ(Quantile(v, 0.9), kInf);
  EXPECT_EQ(Quantile(v, 1.0), kInf);
  EXPECT_TRUE(std::isnan(Median({-kInf, kInf})));
  EXPECT_TRUE(std::isnan(Median({})));
  const Spread empty = Describe({});
  EXPECT_EQ(empty.n, 0);
  EXPECT_TRUE(std::isnan(empty.median));
}

TEST(RankTestsTest, QuantileRefusesNaNAndBadProbability) {
  EXPECT_THROW(Quantile({1.0, kNaN, 2.0}, 0.5), std::invalid_argument);
  EXPECT_THROW(Describe({kNaN}), std::invalid_argument);
  EXPECT_THROW(Quantile({1.0, 2.0}, 1.5), std::invalid_argument);
  EXPECT_THROW(Quantile({1.0, 2.0}, kNaN), std::invalid_argument);
}

// Six positive differences: only one of the 2^6 sign patterns is as extreme on each side, so
// p = 2 / 64; swapping the samples mirrors W+ to n(n+1)/2 - W+ with the same p.
TEST(RankTestsTest, SignedRankAllPositiveSixPairs) {
  const std::vector<double> a = {1.2, 2.3, 0.4, 5.0, 3.3, 0.9};
  const std::vector<double> b = {1.0, 2.0, 0.3, 4.0, 3.0, 0.1};
  const SignedRankTest t = WilcoxonSignedRank(a, b);
  EXPECT_EQ(t.n, 6);
  EXPECT_DOUBLE_EQ(t.statistic, 21.0);
  EXPECT_DOUBLE_EQ(t.p_value, 0.03125);
  EXPECT_TRUE(t.exact);
  const SignedRankTest swapped = WilcoxonSignedRank(b, a);
  EXPECT_DOUBLE_EQ(swapped.statistic, 0.0);
  EXPECT_DOUBLE_EQ(swapped.p_value, 0.03125);
}

// d = a - b = 0 1.5 -1.5 2 2 2 -3 0 4 5 -0.5 5: the two zeros are dropped, the tied |d| share
// average ranks (1.5 -> 2.5, 2 -> 5, 5 -> 9.5); brute force over 2^10 patterns: W+ = 44.5,
// p = 0.08984375 (= 92 / 1024).
TEST(RankTestsTest, SignedRankTiesAndZerosMatchEnumeration) {
  const std::vector<double> a = {1.0, 2.5, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0};
  const std::vector<double> b = {1.0, 1.0, 4.5, 2.0, 3.0, 4.0, 10.0, 8.0, 5.0, 5.0, 11.5, 7.0};
  const SignedRankTest t = WilcoxonSignedRank(a, b);
  EXPECT_EQ(t.n, 10);
  EXPECT_DOUBLE_EQ(t.statistic, 44.5);
  EXPECT_NEAR(t.p_value, 0.08984375, 1e-15);
  EXPECT_TRUE(t.exact);
}

// A diverged run (inf) against a finite one is an infinite difference ranked largest, tied with
// the -inf one; inf against inf is a zero and dropped. d = 0.125 -0.125 inf 0 0.125 0.25 -0.0625
// -0.125 -inf: ranks 3.5 (x4), 7.5 (x2), 6, 1; brute force: W+ = 20.5, p = 0.8046875.
TEST(RankTestsTest, SignedRankInfiniteDifferences) {
  const std::vector<double> a = {0.375, 0.5, kInf, kInf, 0.75, 0.625, 0.25, 1.0, 0.5};
  const std::vector<double> b = {0.25, 0.625, 0.75, kInf, 0.625, 0.375, 0.3125, 1.125, kInf};
  const SignedRankTest t = WilcoxonSignedRank(a, b);
  EXPECT_EQ(t.n, 8);
  EXPECT_DOUBLE_EQ(t.statistic, 20.5);
  EXPECT_NEAR(t.p_value, 0.8046875, 1e-15);
  EXPECT_TRUE(t.exact);
}

// 30 nonzero differences with ties (17 distinct |d|): the normal approximation with the tie
// and continuity corrections, from its formula in Python: W+ = 380.5, p = 0.0023948516054357327.
TEST(RankTestsTest, SignedRankNormalApproximationThirtyPairs) {
  std::vector<double> a, b;
  for (int i = 0; i < 30; ++i) {
    a.push_back(((7 * i) % 11) * 0.5 + (i % 3));
    b.push_back(((5 * i) % 13) * 0.25 + 0.875);
  }
  const SignedRankTest t = WilcoxonSignedRank(a, b);
  EXPECT_EQ(t.n, 30);
  EXPECT_FALSE(t.exact);
  EXPECT_DOUBLE_EQ(t.statistic, 380.5);
  EXPECT_NEAR(t.p_value, 0.0023948516054357327, 1e-12);
}

// The exact distribution is used up to n = 25 (all positive: p = 2 / 2^25), the normal one from
// 26; identical samples give n = 0 and p = 1.
TEST(RankTestsTest, SignedRankExactLimitAndNoDifferences) {
  std::vector<double> a(25), b(25, 0.0);
  for (int i = 0; i < 25; ++i) a[i] = i + 1.0;
  const SignedRankTest exact = WilcoxonSignedRank(a, b);
  EXPECT_TRUE(exact.exact);
  EXPECT_DOUBLE_EQ(exact.p_value, std::ldexp(1.0, -24));
  a.push_back(26.0);
  b.push_back(0.0);
  EXPECT_FALSE(WilcoxonSignedRank(a, b).exact);
  const SignedRankTest none = WilcoxonSignedRank(a, a);
  EXPECT_EQ(none.n, 0);
  EXPECT_DOUBLE_EQ(none.p_value, 1.0);
}

TEST(RankTestsTest, SignedRankRefusesMismatchedSizesAndNaN) {
  try {
    WilcoxonSignedRank({1.0, 2.0}, {1.0});
    FAIL() << "no InputError for unpaired samples";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("paired"), std::string::npos) << e.what();
  }
  EXPECT_THROW(WilcoxonSignedRank({1.0, kNaN}, {1.0, 2.0}), std::invalid_argument);
}

// Textbook critical values (0.05 at 1, 2, 10 and 50 dof, 0.001 at 1 dof), the closed forms
// erfc(sqrt(x/2)) for 1 dof and exp(-x/2) for 2 dof across the series and continued-fraction
// ranges, and the ends.
TEST(RankTestsTest, ChiSquareSurvivalKnownValues) {
  EXPECT_NEAR(ChiSquareSurvival(3.841459, 1), 0.05, 1e-7);
  EXPECT_NEAR(ChiSquareSurvival(5.991465, 2), 0.05, 1e-7);
  EXPECT_NEAR(ChiSquareSurvival(18.307038, 10), 0.05, 1e-7);
  EXPECT_NEAR(ChiSquareSurvival(67.504807, 50), 0.05, 1e-7);
  EXPECT_NEAR(ChiSquareSurvival(10.827566, 1), 0.001, 1e-8);
  for (double x : {0.01, 0.5, 1.0, 2.9, 3.1, 8.0, 30.0, 100.0}) {
    EXPECT_NEAR(ChiSquareSurvival(x, 1), std::erfc(std::sqrt(x / 2)), 1e-14) << "x=" << x;
    EXPECT_NEAR(ChiSquareSurvival(x, 2) / std::exp(-x / 2), 1.0, 1e-13) << "x=" << x;
  }
  EXPECT_EQ(ChiSquareSurvival(0.0, 3), 1.0);
  EXPECT_EQ(ChiSquareSurvival(kInf, 3), 0.0);
  EXPECT_THROW(ChiSquareSurvival(1.0, 0), std::invalid_argument);
  EXPECT_THROW(ChiSquareSurvival(kNaN, 1), std::invalid_argument);
}

// Four blocks of three treatments without ties, by hand: ranks (1 2 3) (1 3 2) (1 2 3) (2 1 3),
// R = 5 8 11, Q = 12 / (4 3 4) (25 + 64 + 121) - 3 4 4 = 4.5, p = exp(-4.5 / 2) at 2 dof.
TEST(RankTestsTest, FriedmanByHand) {
  const std::vector<std::vector<double>> scores = {
      {0.10, 0.20, 0.30}, {0.15, 0.40, 0.35}, {0.20, 0.25, 0.90}, {0.50, 0.45, 0.60}};
  const FriedmanTest t = Friedman(scores);
  EXPECT_EQ(t.blocks, 4);
  EXPECT_EQ(t.treatments, 3);
  EXPECT_NEAR(t.statistic, 4.5, 1e-12);
  EXPECT_NEAR(t.p_value, std::exp(-2.25), 1e-12);
  ASSERT_EQ(t.mean_ranks.size(), 3u);
  EXPECT_DOUBLE_EQ(t.mean_ranks[0], 1.25);
  EXPECT_DOUBLE_EQ(t.mean_ranks[1], 2.0);
  EXPECT_DOUBLE_EQ(t.mean_ranks[2], 2.75);
}

// Ties within blocks get average ranks and the statistic the tie correction (one block all tied,
// two with a pair): from the formula in Python, mean ranks 1.7 1.9 2.4, Q = 1.7333333333333,
// and p = exp(-Q/2) for 3 treatments.
TEST(RankTestsTest, FriedmanWithTies) {
  const std::vector<std::vector<double>> scores = {
      {1, 1, 2}, {3, 1, 2}, {2, 2, 2}, {1, 2, 3}, {0.5, 0.7, 0.6}};
  const FriedmanTest t = Friedman(scores);
  EXPECT_NEAR(t.statistic, 1.733333333333339, 1e-12);
  EXPECT_NEAR(t.p_value, 0.42035038450868073, 1e-12);
  ASSERT_EQ(t.mean_ranks.size(), 3u);
  EXPECT_NEAR(t.mean_ranks[0], 1.7, 1e-15);
  EXPECT_NEAR(t.mean_ranks[1], 1.9, 1e-15);
  EXPECT_NEAR(t.mean_ranks[2], 2.4, 1e-15);
}

// One block, one treatment or nothing but ties leave nothing to test (p = 1); ragged or NaN
// scores are refused.
TEST(RankTestsTest, FriedmanDegenerateAndBadInput) {
  EXPECT_DOUBLE_EQ(Friedman({{1.0, 2.0, 3.0}}).p_value, 1.0);
  EXPECT_DOUBLE_EQ(Friedman({{1.0}, {2.0}}).p_value, 1.0);
  EXPECT_DOUBLE_EQ(Friedman({}).p_value, 1.0);
  const FriedmanTest all_tied = Friedman({{1.0, 1.0}, {kInf, kInf}});
  EXPECT_DOUBLE_EQ(all_tied.statistic, 0.0);
  EXPECT_DOUBLE_EQ(all_tied.p_value, 1.0);
  EXPECT_THROW(Friedman({{1.0, 2.0}, {1.0}}), std::invalid_argument);
  EXPECT_THROW(Friedman({{1.0, 2.0}, {kNaN, 1.0}}), std::invalid_argument);
}

// By hand: sorted 0.005 0.01 0.03 0.04 times 4 3 2 1 = 0.02 0.03 0.06 0.04, made monotone
// (0.04 -> 0.06), back in input order; large p-values are capped at 1.
TEST(RankTestsTest, HolmAdjustKnownVector) {
  const std::vector<double> adjusted = HolmAdjust({0.01, 0.04, 0.03, 0.005});
  const std::vector<double> expected = {0.03, 0.06, 0.06, 0.02};
  ASSERT_EQ(adjusted.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(adjusted[i], expected[i], 1e-15) << i;
  EXPECT_EQ(HolmAdjust({0.6, 0.5}), (std::vector<double>{1.0, 1.0}));
  EXPECT_TRUE(HolmAdjust({}).empty());
  EXPECT_THROW(HolmAdjust({0.1, kNaN}), std::invalid_argument);
  EXPECT_THROW(HolmAdjust({1.5}), std::invalid_argument);
}

}  // namespace
}  // namespace usvid
