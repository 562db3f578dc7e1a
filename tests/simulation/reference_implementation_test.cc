// `usvid simulate --inputs` against an independent implementation of the equations
// (issue 3 acceptance): odin3dof from docs/model.md#odin3dof written with its matrices M, C(nu),
// D(nu) and a linear solve, msd from m x'' + d x' + k x = f, both with classical RK4 and the
// input held over each step. Over 300 s every channel agrees to 1e-4 of its range.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <sstream>

#include "core/csv_dataset.h"
#include "core/parse_number.h"
#include "tests/apps/run_usvid.h"

namespace usvid {
namespace {

using testing::FreshTempDir;
using testing::RunUsvid;
using testing::WriteText;

// Domain.md 2.2 as matrices: eta' = R(psi) nu, M nu' = tau - C(nu) nu - D(nu) nu.
Eigen::Matrix<double, 6, 1> Odin3DofReference(const Eigen::Matrix<double, 6, 1>& x,
                                              const Eigen::Vector3d& tau) {
  const double psi = x(2), u = x(3), v = x(4), r = x(5);
  Eigen::Matrix3d M = Eigen::Vector3d(4935, 4935, 20928).asDiagonal();
  Eigen::Matrix3d C;
  C << 0, 0, -4935 * v, 0, 0, 4935 * u, 4935 * v, -4935 * u, 0;
  Eigen::Matrix3d D;
  D << 50 + 243 * std::abs(u), 0, 0, 0, 200 + 2000 * std::abs(v), 0, 0, 1281,
      1281 + 2975 * std::abs(r);
  const Eigen::Vector3d nu(u, v, r);
  Eigen::Matrix<double, 6, 1> dx;
  dx(0) = std::cos(psi) * u - std::sin(psi) * v;
  dx(1) = std::sin(psi) * u + std::cos(psi) * v;
  dx(2) = r;
  dx.tail<3>() = M.lu().solve(tau - C * nu - D * nu);
  return dx;
}

template <typename F, typename X, typename U>
X Rk4(const F& f, const X& x, const U& u, double h) {
  const X k1 = f(x, u), k2 = f(x + h / 2 * k1, u), k3 = f(x + h / 2 * k2, u), k4 = f(x + h * k3, u);
  return x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
}

class ReferenceImplementationTest : public ::testing::Test {
 protected:
  // Piecewise-constant random levels, changing every 2 to 8 s.
  static Eigen::MatrixXd RandomSteps(int rows, double dt, const Eigen::VectorXd& lo,
                                     const Eigen::VectorXd& hi, uint64_t seed) {
    std::mt19937_64 rng(seed);
    Eigen::MatrixXd u(rows, lo.size());
    for (int c = 0; c < lo.size(); ++c) {
      std::uniform_real_distribution<double> level(lo(c), hi(c)), hold(2.0, 8.0);
      double value = level(rng), until = hold(rng);
      for (int k = 0; k < rows; ++k) {
        if (k * dt >= until) {
          value = level(rng);
          until += hold(rng);
        }
        u(k, c) = value;
      }
    }
    return u;
  }

  static void ExpectAgree(const Dataset& got, const std::vector<std::string>& names,
                          const Eigen::MatrixXd& want) {
    for (size_t c = 0; c < names.size(); ++c) {
      const Eigen::VectorXd& g = got[names[c]];
      const double range = want.col(c).maxCoeff() - want.col(c).minCoeff();
      const double err = (g - want.col(c)).cwiseAbs().maxCoeff();
      EXPECT_LE(err, 1e-4 * range) << names[c] << " error " << err << " range " << range;
    }
  }
};

// odin3dof over 300 s of random surge, sway and yaw inputs, --dt 0.05.
TEST_F(ReferenceImplementationTest, Odin3DofMatchesMatrixForm) {
  const double dt = 0.05;
  const int rows = 6001;
  Eigen::VectorXd lo(3), hi(3);
  lo << 5000, -2000, -6000;
  hi << 40000, 2000, 6000;
  const Eigen::MatrixXd tau = RandomSteps(rows, dt, lo, hi, 7);
  Eigen::MatrixXd want(rows, 6);
  Eigen::Matrix<double, 6, 1> x;
  x << 0, 0, 0, 8, 0, 0;
  std::ostringstream csv;
  csv.precision(17);
  csv << "t,tau_x,tau_y,tau_n,u\n";
  for (int k = 0; k < rows; ++k) {
    want.row(k) = x.transpose();
    csv << k * dt << ',' << tau(k, 0) << ',' << tau(k, 1) << ',' << tau(k, 2) << ','
        << (k == 0 ? "8" : "") << '\n';
    x = Rk4([](const auto& s, const auto& u) { return Odin3DofReference(s, u); }, x,
            Eigen::Vector3d(tau.row(k).transpose()), dt);
  }
  const auto dir = FreshTempDir();
  WriteText(dir / "in.csv", csv.str());
  const auto r = RunUsvid("simulate --vessel odin3dof --inputs " + (dir / "in.csv").string() +
                          " --dt 0.05 --out " + (dir / "out.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Dataset got = ReadDatasetCsv((dir / "out.csv").string());
  ASSERT_EQ(got.rows(), rows);
  ExpectAgree(got, {"north", "east", "psi", "u", "v", "r"}, want);
}

// msd over 300 s of random force steps, --dt 0.01, starting from the first row's x and v.
TEST_F(ReferenceImplementationTest, MsdMatchesSecondOrderEquation) {
  const double dt = 0.01;
  const int rows = 30001;
  Eigen::VectorXd lo(1), hi(1);
  lo << -10;
  hi << 10;
  const Eigen::MatrixXd f = RandomSteps(rows, dt, lo, hi, 11);
  auto msd = [](const Eigen::Vector2d& s, const double& force) {
    return Eigen::Vector2d(s(1), (force - 1.0 * s(1) - 2.0 * s(0)) / 10.0);
  };
  Eigen::MatrixXd want(rows, 2);
  Eigen::Vector2d x(0.5, -0.25);
  std::ostringstream csv;
  csv.precision(17);
  csv << "t,f,x,v\n";
  for (int k = 0; k < rows; ++k) {
    want.row(k) = x.transpose();
    csv << k * dt << ',' << f(k, 0) << ',' << (k == 0 ? "0.5,-0.25" : ",") << '\n';
    x = Rk4(msd, x, f(k, 0), dt);
  }
  const auto dir = FreshTempDir();
  WriteText(dir / "in.csv", csv.str());
  const auto r = RunUsvid("simulate --vessel msd --inputs " + (dir / "in.csv").string() +
                          " --dt 0.01 --out " + (dir / "out.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExpectAgree(ReadDatasetCsv((dir / "out.csv").string()), {"x", "v"}, want);
}

}  // namespace
}  // namespace usvid
