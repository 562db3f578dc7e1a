// The covariance of one parameter block theta of a Ceres problem in which every residual block
// depends on theta and on at most one other parameter block (multiple shooting: each segment's
// initial state). The other blocks are eliminated one at a time by the Schur complement,
//   I_theta = sum_s (B_s' B_s - B_s' A_s (A_s' A_s)^-1 A_s' B_s),   C = I_theta^-1,
// with A_s, B_s the Jacobians of segment s's residuals in its state (in the tangent space of its
// manifold; none for a constant block) and in theta. That is the theta block of (J' J)^-1, as
// ceres::Covariance computes it, but held a residual block at a time: ceres::Covariance's sparse
// QR of the whole Jacobian took 170 MB on a 20-minute log, and grows with the log.
#pragma once

#include <ceres/problem.h>

#include <Eigen/Core>

namespace usvid {

// False when a block's information is singular (reciprocal condition number below 1e-14, as
// ceres::Covariance refuses) or a residual block has a loss function or a second other block.
// `covariance` is size x size, size = the tangent size of theta.
bool SchurCovariance(const ceres::Problem& problem, const double* theta,
                     Eigen::MatrixXd* covariance);

}  // namespace usvid
