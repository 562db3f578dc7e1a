#include "simulation/segment_length.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace usvid {

double HullLengthSeconds(const Dataset& data, const VesselInfo& info) {
  if (!(info.length_m > 0)) return 0.0;
  std::vector<double> speed;
  const Channel* U = data.Find("U");
  const Channel* u = data.Find("u");
  const Channel* v = data.Find("v");
  for (Eigen::Index k = 0; k < data.rows(); ++k) {
    if (U != nullptr && U->IsSampled(k)) {
      speed.push_back(std::abs(U->Value(k)));
    } else if (u != nullptr && u->IsSampled(k)) {
      const double vk = v != nullptr && v->IsSampled(k) ? v->Value(k) : 0.0;
      speed.push_back(std::hypot(u->Value(k), vk));
    }
  }
  if (speed.empty()) return 0.0;
  std::nth_element(speed.begin(), speed.begin() + speed.size() / 2, speed.end());
  const double median = speed[speed.size() / 2];
  return median > 0 ? info.length_m / median : 0.0;
}

double AutomaticSegmentSeconds(const Dataset& data, const VesselInfo& info) {
  constexpr double kMinimum = 10.0;
  const double hull = HullLengthSeconds(data, info);
  return hull > 0 ? std::max(kMinimum, std::round(1.5 * hull)) : kMinimum;
}

}  // namespace usvid
