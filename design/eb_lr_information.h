// eb-lr's own covariance, for a design study of eb-lr on eb2dof (design/information.h).
// eb-lr is not the efficient estimator the Cramer-Rao bound describes. It estimates in two
// stages, and each stage uses a part of the record (methods/eb_lr/eb_lr.h):
//  1. sigma from the steady windows alone, one row per window and equation i. In acceleration
//     units the row says that the window's mean acceleration, (s_i(end) - s_i(start)) / T with
//     s the spline-smoothed state, is f_i(x_mean, tau_mean; p), f the vessel's derivative. Its
//     error has two parts: the mean state's noise, sum_k (df_i/dx_k)^2 sd_k^2 / n over the n
//     samples, and the smoothed end points', 2 sd_s,i^2 / T^2. The second dominates on windows
//     of a few seconds: sd_s,i, the smoothed state's error at the windows' ends, is measured on
//     the probe's noisy run against the noise-free trial, smoothed as eb-lr smooths (the spline
//     broken at the inputs' steps). The information is sum over rows of df_i/dp^T df_i/dp / var;
//     the masses do not enter a settled state (their columns are 0 there).
//  2. The masses from the transients, sigma held at its estimate. Their own noise is the
//     record's information I_MM (a settled state says nothing of a mass). Sigma's error carries
//     over as eb-lr's regression carries it: its rows are int m dx_i = int (tau_i - sigma_i) dt
//     over the transient pieces (transient_pieces.h), A c = b, and an error ds moves b by
//     -G ds (G_pj = int phi_j dt), so dM = -K ds with K = (A^T A)^-1 A^T G.
// So Cov_ss = I_W^-1, Cov_MM = I_MM^-1 + K Cov_ss K^T, Cov_Ms = -K Cov_ss.
// Everything in relative units (parameters as ratios to their nominal values), in eb2dof's
// parameter order; the masses are its kInertia group. Throws InputError when the windows do
// not pin sigma.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "core/dataset.h"
#include "design/information.h"

namespace usvid::design {

// record_information: the Fisher information of the whole record (the segments' initial states
// taken out); trial: the noise-free record; noisy: a noisy run of it (the probe's); windows:
// eb-lr's steady windows on that run, [start, end] in s.
Eigen::MatrixXd EbLrCovariance(const Eigen::MatrixXd& record_information, const Dataset& trial,
                               const Dataset& noisy,
                               const std::vector<std::pair<double, double>>& windows,
                               const NoiseModel& noise);

}  // namespace usvid::design
