#include "core/angles.h"

#include <cmath>
#include <numbers>

namespace usvid {

Eigen::VectorXd UnwrappedAngle(const Eigen::VectorXd& angle) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  Eigen::VectorXd out = angle;
  double last = NAN;  // the previous finite sample, unwrapped
  for (Eigen::Index k = 0; k < out.size(); ++k) {
    if (!std::isfinite(out(k))) continue;
    if (std::isfinite(last)) out(k) -= kTwoPi * std::round((out(k) - last) / kTwoPi);
    last = out(k);
  }
  return out;
}

}  // namespace usvid
