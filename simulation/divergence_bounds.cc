#include "simulation/divergence_bounds.h"

#include <algorithm>
#include <cmath>

#include "simulators/vessel.h"

namespace usvid {

DivergenceBounds::DivergenceBounds(const std::vector<std::string>& channels, const Dataset& data) {
  for (const std::string& c : channels) {
    double peak = 1e-3;
    if (!IsPositionOrHeading(c) && c != "x" && data.Has(c)) {
      for (double value : data[c])
        peak = std::isfinite(value) ? std::max(peak, std::abs(value)) : peak;
      bounds_.push_back(10.0 * peak);
    } else {
      bounds_.push_back(INFINITY);
    }
  }
}

int DivergenceBounds::Exceeded(const Eigen::VectorXd& x) const {
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (!std::isfinite(x(i)) || std::abs(x(i)) > bounds_[static_cast<size_t>(i)])
      return static_cast<int>(i);
  return -1;
}

}  // namespace usvid
