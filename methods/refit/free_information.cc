#include "methods/refit/free_information.h"

#include <ceres/ceres.h>

#include <Eigen/QR>
#include <Eigen/Sparse>

namespace usvid::refit {

Eigen::MatrixXd FreeInformation(ceres::Problem& problem, double* theta,
                                const std::vector<double*>& starts, int channels) {
  ceres::Problem::EvaluateOptions eo;
  eo.parameter_blocks.push_back(theta);
  for (double* x : starts) eo.parameter_blocks.push_back(x);
  ceres::CRSMatrix crs;
  problem.Evaluate(eo, nullptr, nullptr, nullptr, &crs);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int r = 0; r < crs.num_rows; ++r)
    for (int k = crs.rows[r]; k < crs.rows[r + 1]; ++k)
      triplets.emplace_back(r, crs.cols[k], crs.values[k]);
  Eigen::SparseMatrix<double> j(crs.num_rows, crs.num_cols);
  j.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::MatrixXd a = Eigen::MatrixXd(j.transpose() * j);
  const Eigen::Index c = channels;
  const Eigen::Index p = crs.num_cols - c * static_cast<Eigen::Index>(starts.size());
  Eigen::MatrixXd info = a.topLeftCorner(p, p);
  for (size_t s = 0; s < starts.size(); ++s) {
    const Eigen::Index at = p + c * static_cast<Eigen::Index>(s);
    const Eigen::MatrixXd ajj = a.block(at, at, c, c);
    const Eigen::MatrixXd atj = a.block(0, at, p, c);
    info -= atj * ajj.completeOrthogonalDecomposition().solve(atj.transpose());
  }
  return 0.5 * (info + info.transpose());
}

}  // namespace usvid::refit
