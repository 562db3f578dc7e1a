// The yaw-rate channel checked against the heading. A gyro reads with a constant offset and a
// scale error of its own, which the heading, from another sensor (a compass, GNSS, or a filter
// that holds the heading to one), does not share. With r = (1 + k) r_true + b, the integral of
// r over a record parts from the heading's change as
//   int_0^t r dt - (psi(t) - psi(0)) = b t + k (psi(t) - psi(0)) + c,
// a straight line in t and psi, fitted by least squares over every row; then
// r_true = (r - b) / (1 + k). A record whose heading spans less than 0.05 rad cannot tell the
// scale from the offset, so k is 0 there. On MARIN's KVLCC2 zig-zags b is +1.0e-4 and
// +0.9e-4 rad/s (k -0.14 % and -0.18 %): a yaw-rate offset that a model fitted to r learns as a
// yaw moment, and whose heading then drifts 0.35 deg a minute
// (docs/data.md#the-gyro-against-the-heading).
#pragma once

#include <Eigen/Core>
#include <string>

#include "core/dataset.h"

namespace usvid {

struct RateCalibration {
  double offset = 0.0;        // b [rad/s]
  double scale_error = 0.0;   // k: the rate reads 1 + k times the heading's change
  double residual_rad = 0.0;  // RMS of the fit's residual [rad]: the heading's disagreement left
};

// Throws InputError naming the data's file when r or the heading is missing or has empty cells,
// the record has fewer than 10 rows, or the scale error is above 20 % (the two channels are not
// one motion in the same units).
RateCalibration EstimateRateCalibration(const Dataset& data, const std::string& heading);

// r_true = (r - b) / (1 + k) at every row.
Eigen::VectorXd CalibratedRate(const Dataset& data, const RateCalibration& calibration);

// "r calibrated against psi: offset 1.02e-04 rad/s, scale error -0.14 %, ..." for a report.
std::string DescribeRateCalibration(const RateCalibration& calibration, const std::string& heading);

}  // namespace usvid
