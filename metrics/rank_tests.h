// Rank-based statistics for `usvid compare`: do two identification methods differ over paired
// cells (same training maneuver, seed and noise)? Ranks, not values, because the scores are
// heavy-tailed (a diverged free run scores +inf) and differ in scale between cells; a rank test
// needs no distributional assumption and treats an infinite score as simply the worst.
//
// - Quantile: type 7 (R's and numpy's default): for sorted x_0..x_{n-1}, h = (n-1) p,
//   lo = floor(h), Q(p) = (1 - (h - lo)) x_lo + (h - lo) x_lo+1. +-inf sort to the ends; an exact
//   order statistic is returned as is, and interpolating towards an infinity gives it (as R;
//   numpy gives NaN there), so only a step from -inf to +inf gives NaN.
// - Wilcoxon signed-rank on d_i = a_i - b_i: zeros dropped (Wilcoxon's convention; a_i == b_i,
//   including inf == inf, is a zero), the n others ranked by |d| (average ranks for ties, an
//   infinite |d| ranks largest), W+ = sum of the ranks of positive d. Exact null distribution of
//   W+ for n <= 25 (counts over doubled ranks, so half ranks stay integral), otherwise normal with
//   mean n(n+1)/4, variance n(n+1)(2n+1)/24 - sum(t^3 - t)/48 over tie groups of size t, and a
//   0.5 continuity correction. Two-sided p = min(1, 2 min(P(W+ <= w), P(W+ >= w))).
// - Friedman on b blocks x k treatments: ranks within each block (1 = smallest, average ranks
//   for ties), R_j their sum for treatment j,
//   Q = [12 / (b k (k+1)) sum_j R_j^2 - 3 b (k+1)] / [1 - sum(t^3 - t) / (b (k^3 - k))],
//   p = P(chi^2_{k-1} >= Q).
// - Holm-Bonferroni: with p sorted ascending p_(1..m), adjusted p_(i) = min(1, max_{j<=i}
//   (m - j + 1) p_(j)); reject p_adj <= alpha controls the family-wise error rate at alpha.
//
// Bad input (NaN anywhere, mismatched sizes, p outside [0, 1]) throws InputError (a
// std::invalid_argument) naming the function, the index and the value.
#pragma once

#include <vector>

namespace usvid {

// Type-7 quantile of v at p in [0, 1]; NaN for an empty v.
double Quantile(std::vector<double> v, double p);
double Median(std::vector<double> v);

struct Spread {
  double median = 0.0;
  double q1 = 0.0;  // 25 % quantile
  double q3 = 0.0;  // 75 % quantile
  int n = 0;
};

// Median and quartiles of v (NaN for an empty v), sorting it once.
Spread Describe(const std::vector<double>& v);

struct SignedRankTest {
  int n = 0;               // nonzero paired differences
  double statistic = 0.0;  // W+, the rank sum of the positive differences
  double p_value = 1.0;    // two-sided; 1 when n == 0
  bool exact = true;       // exact null distribution (n <= 25) or normal approximation
};

// Paired test on a[i] - b[i]: a positive W+ beyond its null mean says a tends to exceed b.
SignedRankTest WilcoxonSignedRank(const std::vector<double>& a, const std::vector<double>& b);

struct FriedmanTest {
  int blocks = 0;
  int treatments = 0;
  double statistic = 0.0;          // tie-corrected Q; 0 when every block is all ties
  double p_value = 1.0;            // 1 with fewer than 2 blocks or treatments
  std::vector<double> mean_ranks;  // per treatment; rank 1 = the smallest value in a block
};

// scores[block][treatment]; every block must have the same number of treatments. Whether higher
// is better does not matter for the test, only for reading mean_ranks.
FriedmanTest Friedman(const std::vector<std::vector<double>>& scores);

// P(chi^2 with dof degrees of freedom >= x), the regularized upper incomplete gamma function
// Q(dof/2, x/2); 1 for x <= 0. Throws for dof < 1 or NaN x.
double ChiSquareSurvival(double x, int dof);

// Holm-Bonferroni step-down adjusted p-values, monotone in p, capped at 1, in p's order.
std::vector<double> HolmAdjust(const std::vector<double>& p);

}  // namespace usvid
