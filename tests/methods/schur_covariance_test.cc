// SchurCovariance (methods/schur_covariance.h): eliminating each segment's initial state block by
// block gives the covariance ceres::Covariance gives from the whole Jacobian, with free, partly
// held (SubsetManifold) and constant segment states; a singular problem is refused as Ceres
// refuses it.
#include "methods/schur_covariance.h"

#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace usvid {
namespace {

// Segment of a two-state decay x1' = -a x1 + b, x2' = -c x2 + a x1, sampled at 0.1 s from its
// own initial state (explicit Euler at 0.01 s: the exact map does not matter, the structure does).
struct SegmentResidual {
  std::vector<std::array<double, 2>> measured;
  template <typename T>
  bool operator()(const T* theta, const T* x0, T* residual) const {
    T x1 = x0[0], x2 = x0[1];
    for (size_t k = 0; k < measured.size(); ++k) {
      residual[2 * k] = (x1 - measured[k][0]) / 0.01;
      residual[2 * k + 1] = (x2 - measured[k][1]) / 0.01;
      for (int i = 0; i < 10; ++i) {
        const T d1 = -theta[0] * x1 + theta[1];
        const T d2 = -theta[2] * x2 + theta[0] * x1;
        x1 += 0.01 * d1;
        x2 += 0.01 * d2;
      }
    }
    return true;
  }
};

constexpr int kSamples = 30;

struct Fixture {
  std::array<double, 3> theta = {0.8, 0.5, 1.3};
  std::vector<std::array<double, 2>> x0;
  ceres::Problem problem;

  // `held`: 0 free states, 1 the second state held (SubsetManifold), 2 the block constant.
  Fixture(int segments, int held, unsigned seed) : x0(segments) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.01);
    std::uniform_real_distribution<double> start(-1.0, 1.0);
    for (int s = 0; s < segments; ++s) {
      x0[s] = {start(rng), start(rng)};
      auto* r = new SegmentResidual;
      double x1 = x0[s][0], x2 = x0[s][1];
      for (int k = 0; k < kSamples; ++k) {
        r->measured.push_back({x1 + noise(rng), x2 + noise(rng)});
        for (int i = 0; i < 10; ++i) {
          const double d1 = -theta[0] * x1 + theta[1], d2 = -theta[2] * x2 + theta[0] * x1;
          x1 += 0.01 * d1;
          x2 += 0.01 * d2;
        }
      }
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<SegmentResidual, 2 * kSamples, 3, 2>(r), nullptr,
          theta.data(), x0[s].data());
      if (held == 1) problem.SetManifold(x0[s].data(), new ceres::SubsetManifold(2, {1}));
      if (held == 2) problem.SetParameterBlockConstant(x0[s].data());
    }
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_SCHUR;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
  }

  Eigen::MatrixXd CeresCovariance() {
    ceres::Covariance::Options co;
    ceres::Covariance covariance(co);
    std::vector<std::pair<const double*, const double*>> blocks = {{theta.data(), theta.data()}};
    EXPECT_TRUE(covariance.Compute(blocks, &problem));
    Eigen::Matrix<double, 3, 3, Eigen::RowMajor> c;
    covariance.GetCovarianceBlock(theta.data(), theta.data(), c.data());
    return c;
  }
};

TEST(SchurCovarianceTest, EqualsCeresCovarianceOfTheWholeJacobian) {
  for (int held = 0; held <= 2; ++held) {
    SCOPED_TRACE("held " + std::to_string(held));
    Fixture f(12, held, 7 + held);
    const Eigen::MatrixXd expected = f.CeresCovariance();
    Eigen::MatrixXd c;
    ASSERT_TRUE(SchurCovariance(f.problem, f.theta.data(), &c));
    ASSERT_EQ(c.rows(), 3);
    EXPECT_LT((c - expected).norm(), 1e-7 * expected.norm()) << c << "\n\n" << expected;
  }
}

struct Sum {
  template <typename T>
  bool operator()(const T* t, T* r) const {
    r[0] = t[0] + t[1] - T(3.0);
    return true;
  }
};

// Information that determines only a combination of theta is singular: refused, as
// ceres::Covariance refuses it.
TEST(SchurCovarianceTest, RefusesASingularProblem) {
  double theta[2] = {1.0, 2.0};
  ceres::Problem problem;
  // r = theta0 + theta1 - 3: only their sum is determined.
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<Sum, 1, 2>(new Sum), nullptr, theta);
  Eigen::MatrixXd c;
  EXPECT_FALSE(SchurCovariance(problem, theta, &c));
}

}  // namespace
}  // namespace usvid
