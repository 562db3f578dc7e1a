// Savitzky-Golay: exact on polynomials up to its order, the textbook weights, zero phase.
#include "preprocessing/savitzky_golay.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "preprocessing/cross_correlation.h"

namespace usvid {
namespace {

class SavitzkyGolayTest : public ::testing::Test {};

// The 5-point quadratic smoother is (-3, 12, 17, 12, -3) / 35 (Savitzky & Golay 1964).
TEST_F(SavitzkyGolayTest, ClassicFivePointWeights) {
  const Eigen::VectorXd w = SavitzkyGolay{5, 2}.Weights(2, 0, 1.0);
  Eigen::VectorXd want(5);
  want << -3, 12, 17, 12, -3;
  EXPECT_LT((w - want / 35.0).cwiseAbs().maxCoeff(), 1e-12);
}

// A cubic is reproduced exactly, value and derivative, at every sample including the ends.
TEST_F(SavitzkyGolayTest, ExactOnPolynomialsIncludingEnds) {
  const double dt = 0.05;
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(200, 0.0, 199 * dt);
  const Eigen::VectorXd y =
      (0.3 * t.array().cube() - 2 * t.array().square() + t.array() - 4).matrix();
  const Eigen::VectorXd dy = (0.9 * t.array().square() - 4 * t.array() + 1).matrix();
  const SavitzkyGolay sg{21, 3};
  EXPECT_LT((sg.Apply(y, dt, 0) - y).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT((sg.Apply(y, dt, 1) - dy).cwiseAbs().maxCoeff(), 1e-8);
}

// Centred windows do not delay a sine's derivative: the estimate of cos is cos, not shifted.
TEST_F(SavitzkyGolayTest, CentredDerivativeHasNoLag) {
  const double dt = 0.05;
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(2001, 0.0, 100.0);
  const Eigen::VectorXd d = SavitzkyGolay{31, 3}.Apply(t.array().sin().matrix(), dt, 1);
  const Eigen::VectorXd truth = t.array().cos().matrix();
  EXPECT_NEAR(EstimateLag(truth, d, 10).lag, 0.0, 1e-3);
  EXPECT_LT((d - truth).segment(15, 1970).cwiseAbs().maxCoeff(), 1e-3);
}

// Bad windows are refused with a message.
TEST_F(SavitzkyGolayTest, BadWindowsThrow) {
  const Eigen::VectorXd y = Eigen::VectorXd::Ones(50);
  EXPECT_THROW((SavitzkyGolay{20, 3}.Apply(y, 0.1, 1)), InputError);
  EXPECT_THROW((SavitzkyGolay{3, 3}.Apply(y, 0.1, 1)), InputError);
  EXPECT_THROW((SavitzkyGolay{51, 3}.Apply(y, 0.1, 1)), InputError);
  EXPECT_THROW((SavitzkyGolay{11, 3}.Apply(y, 0.0, 1)), InputError);
}

}  // namespace
}  // namespace usvid
