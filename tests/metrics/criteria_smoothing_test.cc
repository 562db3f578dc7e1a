// The smoothing the maneuver criteria read through (metrics/criteria_smoothing.h): it takes
// noise out of a channel on a uniform grid, leaves a clean one as it is, and leaves a channel
// whose grid is not uniform (a gap, a log's jitter) untouched.
#include "metrics/criteria_smoothing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace usvid {
namespace {

Eigen::VectorXd Grid(int n, double dt) { return Eigen::VectorXd::LinSpaced(n, 0.0, (n - 1) * dt); }

Eigen::VectorXd Heading(const Eigen::VectorXd& t) {
  return (0.4 * (2 * M_PI * t.array() / 120.0).sin() + 0.01 * t.array()).matrix();
}

TEST(CriteriaSmoothingTest, ACleanChannelIsLeftAsItIs) {
  const Eigen::VectorXd t = Grid(3000, 0.1), x = Heading(t);
  EXPECT_LT((SmoothedForCriteria(t, x) - x).cwiseAbs().maxCoeff(), 1e-6);
}

// White noise of 0.01 rad on a heading swinging 0.4 rad: the smoothed channel is within a third
// of the noise of the clean one everywhere but the first and last five seconds, and its RMS
// error is below 0.15 of the noise.
TEST(CriteriaSmoothingTest, NoiseIsTakenOut) {
  const Eigen::VectorXd t = Grid(3000, 0.1), clean = Heading(t);
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.01);
  Eigen::VectorXd x = clean;
  for (double& v : x) v += noise(rng);
  const Eigen::VectorXd error = SmoothedForCriteria(t, x) - clean;
  EXPECT_LT(error.segment(50, 2900).cwiseAbs().maxCoeff(), 0.0033);
  EXPECT_LT(std::sqrt(error.squaredNorm() / error.size()), 0.0015);
}

TEST(CriteriaSmoothingTest, AGridThatIsNotUniformIsLeftAsItIs) {
  Eigen::VectorXd t = Grid(500, 0.1);
  t.tail(200).array() += 2.0;  // a 2 s gap
  Eigen::VectorXd x = Heading(t);
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (double& v : x) v += noise(rng);
  EXPECT_EQ(SmoothedForCriteria(t, x), x);
  EXPECT_EQ(SmoothedForCriteria(Grid(5, 0.1), x.head(5)), x.head(5));  // too few samples
}

}  // namespace
}  // namespace usvid
