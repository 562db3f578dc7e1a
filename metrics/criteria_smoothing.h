// The channels a maneuver's criteria are read from (zigzag_response.h, turning_response.h),
// smoothed first. A zig-zag's overshoot is the furthest the heading goes; on a noisy record that
// furthest sample is a noise peak, so the overshoot read from the raw heading grows with the
// noise: on a simulated KVLCC2 20/20 zig-zag with 2 % noise (of each channel's standard
// deviation) the first two overshoots read 0.9 and 1.3 deg high, with 0.5 % noise 0.2 and
// 0.3 deg. The heading at the execute, the origin of every overshoot, is one noisy sample too.
// A turning circle's heading crosses 90 and 180 deg early or late by its noise (its unwrapped
// heading's standard deviation is radians, so 2 % of it is degrees), and its positions are read
// at that instant.
//
// The smoothing spline with its automatic lambda (preprocessing/smoothing_spline.h) takes the
// noise out and leaves a clean record, a simulation's or a replay's, as it is: its noise
// estimate is then near zero, and the spline near the interpolating one. So a measured record
// and a model's replay are read by the same rule. Only samples on a uniform grid are smoothed
// (every interval within 5 % of the median, at least 8 samples); a record with gaps, or a
// channel sampled at its own rate between empty cells, is read as it is.
#pragma once

#include <Eigen/Core>

namespace usvid {

// `x` sampled at times `t` (finite, increasing), smoothed as above; `x` itself when its grid is
// not uniform.
Eigen::VectorXd SmoothedForCriteria(const Eigen::Ref<const Eigen::VectorXd>& t,
                                    const Eigen::Ref<const Eigen::VectorXd>& x);

}  // namespace usvid
