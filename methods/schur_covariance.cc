#include "methods/schur_covariance.h"

#include <ceres/cost_function.h>
#include <ceres/manifold.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <map>
#include <vector>

namespace usvid {
namespace {

constexpr double kMinReciprocalCondition = 1e-14;

// The Jacobian in the block's tangent space: row-major ambient columns times the manifold's
// PlusJacobian (ambient x tangent).
Eigen::MatrixXd Tangent(const ceres::Problem& problem, const double* block,
                        const Eigen::MatrixXd& ambient) {
  const ceres::Manifold* manifold = problem.GetManifold(block);
  if (manifold == nullptr) return ambient;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> plus(
      manifold->AmbientSize(), manifold->TangentSize());
  manifold->PlusJacobian(block, plus.data());
  return ambient * plus;
}

bool WellConditioned(const Eigen::MatrixXd& information) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(information, Eigen::EigenvaluesOnly);
  const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
  return eig.eigenvalues().minCoeff() > kMinReciprocalCondition * largest && largest > 0;
}

// The information a segment's state shares with theta, summed over its residual blocks.
struct Nuisance {
  Eigen::MatrixXd aa;  // A' A
  Eigen::MatrixXd ab;  // A' B
};

}  // namespace

bool SchurCovariance(const ceres::Problem& problem, const double* theta,
                     Eigen::MatrixXd* covariance) {
  const int k = problem.ParameterBlockTangentSize(theta);
  Eigen::MatrixXd information = Eigen::MatrixXd::Zero(k, k);
  std::map<const double*, Nuisance> nuisances;
  std::vector<ceres::ResidualBlockId> ids;
  problem.GetResidualBlocks(&ids);
  for (const ceres::ResidualBlockId id : ids) {
    if (problem.GetLossFunctionForResidualBlock(id) != nullptr) return false;
    std::vector<double*> blocks;
    problem.GetParameterBlocksForResidualBlock(id, &blocks);
    const ceres::CostFunction* cost = problem.GetCostFunctionForResidualBlock(id);
    const int m = cost->num_residuals();
    std::vector<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> ambient;
    std::vector<double*> jacobians;
    for (double* block : blocks) {
      ambient.emplace_back(m, problem.ParameterBlockSize(block));
      jacobians.push_back(ambient.back().data());
    }
    Eigen::VectorXd residuals(m);
    if (!cost->Evaluate(blocks.data(), residuals.data(), jacobians.data())) return false;
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(m, k);
    const double* other = nullptr;
    Eigen::MatrixXd a;
    for (size_t i = 0; i < blocks.size(); ++i) {
      if (problem.IsParameterBlockConstant(blocks[i])) continue;
      if (blocks[i] == theta) {
        b = Tangent(problem, theta, ambient[i]);
      } else if (other == nullptr) {
        other = blocks[i];
        a = Tangent(problem, other, ambient[i]);
      } else {
        return false;  // two other blocks: not a multiple-shooting problem
      }
    }
    information.noalias() += b.transpose() * b;
    if (other == nullptr || a.cols() == 0) continue;
    Nuisance& n = nuisances[other];
    if (n.aa.size() == 0) {
      n.aa = Eigen::MatrixXd::Zero(a.cols(), a.cols());
      n.ab = Eigen::MatrixXd::Zero(a.cols(), k);
    }
    n.aa.noalias() += a.transpose() * a;
    n.ab.noalias() += a.transpose() * b;
  }
  for (const auto& [block, n] : nuisances) {
    if (!WellConditioned(n.aa)) return false;
    information -= n.ab.transpose() * n.aa.ldlt().solve(n.ab);
  }
  information = 0.5 * (information + information.transpose());
  if (!WellConditioned(information)) return false;
  *covariance = information.ldlt().solve(Eigen::MatrixXd::Identity(k, k));
  return true;
}

}  // namespace usvid
