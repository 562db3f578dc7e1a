#include "core/stretches.h"

#include <cmath>

#include "core/dataset.h"

namespace usvid {

double GapLimit(const Eigen::Ref<const Eigen::VectorXd>& t, double factor) {
  return t.size() < 2 ? INFINITY : factor * MedianInterval(t);
}

std::vector<Stretch> Stretches(const Eigen::Ref<const Eigen::VectorXd>& t, double factor) {
  std::vector<Stretch> out;
  if (t.size() == 0) return out;
  const double limit = GapLimit(t, factor);
  Eigen::Index first = 0;
  for (Eigen::Index k = 1; k < t.size(); ++k)
    if (t(k) - t(k - 1) > limit) {
      out.push_back({first, k});
      first = k;
    }
  out.push_back({first, t.size()});
  return out;
}

}  // namespace usvid
