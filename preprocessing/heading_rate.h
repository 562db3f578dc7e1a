// The rate of turn of a vessel logged without a gyro (a GPS-only boat): the heading unwrapped
// (jumps of more than pi between samples taken as wraps), then the first derivative of its
// smoothing spline with automatic lambda (smoothing_spline.h) on the data's median interval.
// Needs a sample in every row of the heading and at least 4 rows.
#pragma once

#include <Eigen/Core>
#include <string>

#include "core/dataset.h"

namespace usvid {

// Throws InputError naming the data's file when the heading is missing or has empty cells.
Eigen::VectorXd RateFromHeading(const Dataset& data, const std::string& heading);

}  // namespace usvid
