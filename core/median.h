// The median of a sample, and the factor that turns a median absolute deviation into a
// standard deviation: the robust scale estimates of the preprocessing (noise levels, sample
// intervals).
#pragma once

#include <algorithm>
#include <iterator>
#include <vector>

namespace usvid {

// 1 / Phi^-1(3/4): MAD * kMadToSd estimates sigma for Gaussian data.
inline constexpr double kMadToSd = 1.482602218505602;

// The median of v (the mean of the two middle values when v has an even size). v must not be
// empty.
inline double SampleMedian(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2 == 1) return *mid;
  return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

}  // namespace usvid
