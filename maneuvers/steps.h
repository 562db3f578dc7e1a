// A piecewise-constant schedule: levels[k] from times[k] on (times ascending, times[0] = 0). The
// random steps, PRBS and the autopilot's courses, throttle and side input are such schedules.
#pragma once

#include <random>
#include <vector>

namespace usvid {

struct Steps {
  std::vector<double> times;
  std::vector<double> levels;

  double At(double t) const;

  // Levels uniform in [lo, hi], each held a time uniform in [min_hold, max_hold], from t = 0
  // while t < duration_s (at least one level). Draws a level, then a hold, from `rng`.
  static Steps Random(double lo, double hi, double min_hold, double max_hold, double duration_s,
                      std::mt19937_64& rng);
};

}  // namespace usvid
