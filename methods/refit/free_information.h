// The information of a refit's free parameters, the segments' initial states taken out: what
// `design` predicts parameter spreads from (RefitOptions::information_only). Compiled once here
// rather than in every vessel's typed refit: its sparse product and decompositions cost each of
// those translation units more than ten seconds.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace ceres {
class Problem;
}

namespace usvid::refit {

// A = J^T J over [theta, x0_1, .., x0_S] (the parameter blocks `theta` and `starts`, each start
// `channels` values), then A_tt - sum_j A_tj A_jj^-1 A_jt: theta's (tangent) information with
// every segment's initial state eliminated.
Eigen::MatrixXd FreeInformation(ceres::Problem& problem, double* theta,
                                const std::vector<double*>& starts, int channels);

}  // namespace usvid::refit
