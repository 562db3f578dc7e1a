// Angles logged modulo 2 pi (a heading in [-pi, pi]) made continuous, as the maneuver analyses
// and derivatives need them.
#pragma once

#include <Eigen/Core>

namespace usvid {

// Each step of more than pi between one finite sample and the next is taken as a wrap and
// undone; NaN samples (unsampled cells) stay NaN and are stepped over. A continuous angle comes
// back unchanged.
Eigen::VectorXd UnwrappedAngle(const Eigen::VectorXd& angle);

}  // namespace usvid
