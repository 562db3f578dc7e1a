// Parameter standard deviations of a least-squares fit whose residuals are normalised (each
// divided by its noise sd): sd_i = sqrt(C_ii s^2), C the covariance (J^T J)^-1 at the solution
// and s^2 = 2 final_cost / (residuals - effective parameters) the residual variance per degree
// of freedom (near 1 when the noise model holds; it scales C when it does not). The one place
// fossen-ceres, nomoto and the diagnosis's effect fitters compute it.
#pragma once

#include <algorithm>
#include <ceres/solver.h>
#include <cmath>
#include <vector>

namespace usvid {

inline double ResidualVariance(const ceres::Solver::Summary& summary) {
  const int dof = std::max(1, summary.num_residuals - summary.num_effective_parameters);
  return 2.0 * summary.final_cost / dof;
}

// sd_i from the diagonal C_ii (a negative diagonal, from round-off, gives 0).
inline double ParameterSd(double covariance_ii, const ceres::Solver::Summary& summary) {
  return std::sqrt(std::max(0.0, covariance_ii * ResidualVariance(summary)));
}

// Every sd of an n x n row-major covariance block.
inline std::vector<double> ParameterSds(const double* covariance, int n,
                                        const ceres::Solver::Summary& summary) {
  std::vector<double> sd;
  for (int i = 0; i < n; ++i) sd.push_back(ParameterSd(covariance[i * n + i], summary));
  return sd;
}

}  // namespace usvid
