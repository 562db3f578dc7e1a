#include "metrics/rank_tests.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

#include "core/error.h"
#include "core/nan.h"

namespace usvid {
namespace {

constexpr int kMaxExactN = 25;
constexpr double kGammaTolerance = 1e-15;  // relative, for the series and continued fraction

void RequireNoNaN(const std::vector<double>& v, const std::string& what) {
  for (size_t i = 0; i < v.size(); ++i)
    if (std::isnan(v[i])) throw InputError(what + ": NaN at index " + std::to_string(i));
}

// Type-7 quantile of an already sorted, NaN-free v.
double SortedQuantile(const std::vector<double>& v, double p) {
  if (v.empty()) return kNaN;
  const double h = (v.size() - 1) * p;
  const size_t lo = static_cast<size_t>(std::floor(h));
  const double frac = h - lo;
  if (frac == 0.0 || v[lo] == v[lo + 1]) return v[lo];
  return (1.0 - frac) * v[lo] + frac * v[lo + 1];  // R's form: infinities stay infinite
}

void RequireProbability(double p, const std::string& what) {
  if (!(p >= 0.0 && p <= 1.0))
    throw InputError(what + ": probability " + std::to_string(p) + " outside [0, 1]");
}

// Twice the average ranks (1-based) of x, integral even for ties; the tie group sizes are added
// to *ties (groups of one included, they contribute t^3 - t = 0).
std::vector<int> DoubledRanks(const std::vector<double>& x, std::vector<int>* ties) {
  std::vector<size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return x[i] < x[j]; });
  std::vector<int> doubled(x.size());
  for (size_t start = 0; start < order.size();) {
    size_t end = start + 1;
    while (end < order.size() && x[order[end]] == x[order[start]]) ++end;
    // Ranks start+1 .. end share their average (start + 1 + end) / 2.
    for (size_t i = start; i < end; ++i) doubled[order[i]] = static_cast<int>(start + 1 + end);
    ties->push_back(static_cast<int>(end - start));
    start = end;
  }
  return doubled;
}

// sum over tie groups of t^3 - t.
double TieSum(const std::vector<int>& ties) {
  double sum = 0.0;
  for (double t : ties) sum += t * t * t - t;
  return sum;
}

double StandardNormalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// The nonzero paired differences a - b; a == b (inf == inf included) is a zero.
std::vector<double> NonzeroDifferences(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size())
    throw InputError("WilcoxonSignedRank: " + std::to_string(a.size()) + " scores against " +
                     std::to_string(b.size()) + "; the samples must be paired");
  RequireNoNaN(a, "WilcoxonSignedRank (first sample)");
  RequireNoNaN(b, "WilcoxonSignedRank (second sample)");
  std::vector<double> d;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) d.push_back(a[i] - b[i]);
  return d;
}

// Exact two-sided p for doubled W+ = w2: the null puts each rank's sign at +-1 with probability
// 1/2, so count the sign patterns for every doubled rank sum.
double ExactSignedRankP(const std::vector<int>& doubled, int w2) {
  const int total = std::accumulate(doubled.begin(), doubled.end(), 0);
  std::vector<double> count(total + 1, 0.0);
  count[0] = 1.0;
  int reach = 0;
  for (int r : doubled) {
    reach += r;
    for (int s = reach; s >= r; --s) count[s] += count[s - r];
  }
  const double patterns = std::ldexp(1.0, static_cast<int>(doubled.size()));
  double below = 0.0, above = 0.0;
  for (int s = 0; s <= total; ++s) {
    if (s <= w2) below += count[s];
    if (s >= w2) above += count[s];
  }
  return std::min(1.0, 2.0 * std::min(below, above) / patterns);
}

double NormalSignedRankP(int n, double w, double tie_sum) {
  const double mean = n * (n + 1.0) / 4.0;
  const double sd = std::sqrt(n * (n + 1.0) * (2.0 * n + 1.0) / 24.0 - tie_sum / 48.0);
  const double below = StandardNormalCdf((w - mean + 0.5) / sd);
  const double above = 1.0 - StandardNormalCdf((w - mean - 0.5) / sd);
  return std::min(1.0, 2.0 * std::min(below, above));
}

// Lower regularized gamma P(a, x) by its power series, for x < a + 1.
double GammaPSeries(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 10000 && std::abs(term) > std::abs(sum) * kGammaTolerance; ++n) {
    term *= x / (a + n);
    sum += term;
  }
  return sum * std::exp(a * std::log(x) - x - std::lgamma(a));
}

// Upper regularized gamma Q(a, x) by its continued fraction
// 1 / (x + 1 - a - 1 (1 - a) / (x + 3 - a - 2 (2 - a) / (x + 5 - a - ...))), evaluated forwards
// with the modified Lentz method, for x >= a + 1.
double GammaQContinuedFraction(double a, double x) {
  constexpr double kTiny = 1e-300;
  const auto guard = [](double v) { return std::abs(v) < kTiny ? kTiny : v; };
  double denom = x + 1.0 - a;
  double c = 1.0 / kTiny, d = 1.0 / guard(denom), fraction = d;
  for (int i = 1; i < 10000; ++i) {
    const double numer = -i * (i - a);
    denom += 2.0;
    d = 1.0 / guard(denom + numer * d);
    c = guard(denom + numer / c);
    fraction *= c * d;
    if (std::abs(c * d - 1.0) < kGammaTolerance) break;
  }
  return fraction * std::exp(a * std::log(x) - x - std::lgamma(a));
}

}  // namespace

double Quantile(std::vector<double> v, double p) {
  RequireProbability(p, "Quantile");
  RequireNoNaN(v, "Quantile");
  std::sort(v.begin(), v.end());
  return SortedQuantile(v, p);
}

double Median(std::vector<double> v) { return Quantile(std::move(v), 0.5); }

Spread Describe(const std::vector<double>& v) {
  RequireNoNaN(v, "Describe");
  std::vector<double> sorted = v;
  std::sort(sorted.begin(), sorted.end());
  return {SortedQuantile(sorted, 0.5), SortedQuantile(sorted, 0.25), SortedQuantile(sorted, 0.75),
          static_cast<int>(v.size())};
}

SignedRankTest WilcoxonSignedRank(const std::vector<double>& a, const std::vector<double>& b) {
  const std::vector<double> d = NonzeroDifferences(a, b);
  std::vector<double> magnitude(d.size());
  std::transform(d.begin(), d.end(), magnitude.begin(), [](double x) { return std::abs(x); });
  std::vector<int> ties;
  const std::vector<int> doubled = DoubledRanks(magnitude, &ties);
  int w2 = 0;
  for (size_t i = 0; i < d.size(); ++i)
    if (d[i] > 0) w2 += doubled[i];
  SignedRankTest test;
  test.n = static_cast<int>(d.size());
  test.statistic = w2 / 2.0;
  test.exact = test.n <= kMaxExactN;
  if (test.n == 0) return test;
  test.p_value = test.exact ? ExactSignedRankP(doubled, w2)
                            : NormalSignedRankP(test.n, test.statistic, TieSum(ties));
  return test;
}

FriedmanTest Friedman(const std::vector<std::vector<double>>& scores) {
  FriedmanTest test;
  test.blocks = static_cast<int>(scores.size());
  test.treatments = scores.empty() ? 0 : static_cast<int>(scores[0].size());
  const int b = test.blocks, k = test.treatments;
  std::vector<double> rank_sum(k, 0.0);
  std::vector<int> ties;
  for (int i = 0; i < b; ++i) {
    const std::string block = "Friedman: block " + std::to_string(i);
    if (static_cast<int>(scores[i].size()) != k)
      throw InputError(block + " has " + std::to_string(scores[i].size()) +
                       " treatments, block 0 has " + std::to_string(k));
    RequireNoNaN(scores[i], block);
    const std::vector<int> doubled = DoubledRanks(scores[i], &ties);
    for (int j = 0; j < k; ++j) rank_sum[j] += doubled[j] / 2.0;
  }
  for (double r : rank_sum) test.mean_ranks.push_back(b > 0 ? r / b : kNaN);
  if (b < 2 || k < 2) return test;
  const double sum_squares =
      std::inner_product(rank_sum.begin(), rank_sum.end(), rank_sum.begin(), 0.0);
  const double correction = 1.0 - TieSum(ties) / (b * (k * k * k - k));
  if (correction <= 0.0) return test;  // every block all ties: nothing to tell apart
  const double raw = 12.0 / (b * k * (k + 1.0)) * sum_squares - 3.0 * b * (k + 1.0);
  test.statistic = std::max(0.0, raw / correction);
  test.p_value = ChiSquareSurvival(test.statistic, k - 1);
  return test;
}

double ChiSquareSurvival(double x, int dof) {
  if (dof < 1) throw InputError("ChiSquareSurvival: dof " + std::to_string(dof) + " < 1");
  if (std::isnan(x)) throw InputError("ChiSquareSurvival: x is NaN");
  if (x <= 0.0) return 1.0;
  if (std::isinf(x)) return 0.0;
  const double a = dof / 2.0, half_x = x / 2.0;
  return half_x < a + 1.0 ? 1.0 - GammaPSeries(a, half_x) : GammaQContinuedFraction(a, half_x);
}

std::vector<double> HolmAdjust(const std::vector<double>& p) {
  for (size_t i = 0; i < p.size(); ++i)
    RequireProbability(p[i], "HolmAdjust: p[" + std::to_string(i) + "]");
  std::vector<size_t> order(p.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t i, size_t j) { return p[i] < p[j]; });
  std::vector<double> adjusted(p.size());
  double running = 0.0;
  for (size_t j = 0; j < order.size(); ++j) {
    running = std::max(running, std::min(1.0, (p.size() - j) * p[order[j]]));
    adjusted[order[j]] = running;
  }
  return adjusted;
}

}  // namespace usvid
