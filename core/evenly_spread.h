// Which of `total` items (rows, segments) to keep when at most `wanted` may be used: indices
// spread evenly over the whole range, so that a bounded share of a long record still sees all
// of it (its start, its end and every regime between).
#pragma once

#include <algorithm>
#include <vector>

namespace usvid {

// Indices i * total / n for i in [0, n), n = min(total, wanted); every index when wanted <= 0.
inline std::vector<long> EvenlySpread(long total, long wanted) {
  const long n = wanted > 0 ? std::min(total, wanted) : total;
  std::vector<long> index;
  index.reserve(static_cast<size_t>(std::max(0L, n)));
  for (long i = 0; i < n; ++i) index.push_back(i * total / n);
  return index;
}

}  // namespace usvid
