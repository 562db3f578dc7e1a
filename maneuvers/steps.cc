#include "maneuvers/steps.h"

#include <algorithm>
#include <cstddef>

namespace usvid {

double Steps::At(double t) const {
  const auto it = std::upper_bound(times.begin(), times.end(), t);
  return levels[std::max<std::ptrdiff_t>(0, (it - times.begin()) - 1)];
}

Steps Steps::Random(double lo, double hi, double min_hold, double max_hold, double duration_s,
                    std::mt19937_64& rng) {
  std::uniform_real_distribution<double> level(lo, hi), hold(min_hold, max_hold);
  Steps s;
  for (double t = 0; t < duration_s || t == 0; t += hold(rng)) {
    s.times.push_back(t);
    s.levels.push_back(level(rng));
  }
  return s;
}

}  // namespace usvid
