// The percentile bootstrap interval of a mean (Efron and Tibshirani 1993, An Introduction to the
// Bootstrap, ch. 13): B resamples of the n values, drawn with replacement, each resample's mean
// m_b; the interval is [Q(a/2), Q(1 - a/2)] of m_1..m_B, a = 1 - level, with type-7 quantiles
// (metrics/rank_tests.h). usvid compare reports it over the held-out runs of a
// cross-validation (harness/cross_validation.h): the runs are the resampled units.
//
// Deterministic: index i of resample b is x mod n of the (b n + i)-th draw of std::mt19937_64
// seeded with `seed` (the engine's sequence is fixed by the standard;
// std::uniform_int_distribution's is not), so the same values, count and seed give the same
// interval on every platform. The modulo's bias is below n / 2^64.
//
// Throws InputError (std::invalid_argument) for a NaN or infinite value, fewer than 1 resample
// or a level outside (0, 1). No values: n = 0, and mean, low and high are NaN.
#pragma once

#include <cstdint>
#include <vector>

namespace usvid {

inline constexpr int kBootstrapResamples = 2000;
inline constexpr double kBootstrapLevel = 0.95;
inline constexpr uint64_t kBootstrapSeed = 1;

struct BootstrapInterval {
  double mean = 0.0;  // of the values themselves
  double low = 0.0, high = 0.0;
  int n = 0;
};

BootstrapInterval BootstrapMean(const std::vector<double>& values,
                                int resamples = kBootstrapResamples, double level = kBootstrapLevel,
                                uint64_t seed = kBootstrapSeed);

}  // namespace usvid
