// Foreign logs' time columns: repaired, and the repair reported.
#include "core/time_repair.h"

#include <gtest/gtest.h>

#include <cmath>

namespace usvid {
namespace {

class TimeRepairTest : public ::testing::Test {};

// A 7.4 Hz logger printed with 3 significant digits repeats stamps; the uniform grid comes back
// within the rounding and strictly increasing.
TEST_F(TimeRepairTest, RebuildsRoundedFixedRateStamps) {
  const int n = 3000;
  const double dt = 0.135264;
  Eigen::VectorXd truth(n), printed(n);
  for (int i = 0; i < n; ++i) {
    truth(i) = i * dt;
    const double step = truth(i) > 0 ? std::pow(10.0, std::floor(std::log10(truth(i))) - 2) : 1;
    printed(i) = std::round(truth(i) / step) * step;
  }
  Dataset d(printed);
  d.Set("x", truth);
  const TimeRepairReport r = RebuildRoundedTime(d, 3);
  EXPECT_TRUE(r.rebuilt);
  EXPECT_GT(r.repeated, 100);
  EXPECT_NEAR(r.dt, dt, 1e-5);
  EXPECT_LT((d.t() - truth).cwiseAbs().maxCoeff(), 0.02);
  EXPECT_EQ(d.rows(), n);
}

// A log that paused is no fixed-rate grid: repeated rows are dropped instead, and counted.
TEST_F(TimeRepairTest, FallsBackToDroppingWhenNotUniform) {
  Eigen::VectorXd t(6);
  t << 0, 1, 1, 2, 50, 51;
  Dataset d(t);
  d.Set("x", Eigen::VectorXd::LinSpaced(6, 0, 5));
  const TimeRepairReport r = RebuildRoundedTime(d, 3);
  EXPECT_FALSE(r.rebuilt);
  EXPECT_EQ(r.dropped, 1);
  EXPECT_EQ(d.rows(), 5);
  EXPECT_DOUBLE_EQ(d["x"](2), 3.0);
}

// Rows that repeat or go back in time are dropped; the first of each stamp is kept.
TEST_F(TimeRepairTest, DropsNonIncreasingRows) {
  Eigen::VectorXd t(6);
  t << 0, 1, 1, 0.5, 2, 3;
  Dataset d(t);
  d.Set("x", Eigen::VectorXd::LinSpaced(6, 0, 5));
  const TimeRepairReport r = DropNonIncreasingRows(d);
  EXPECT_EQ(r.repeated, 1);
  EXPECT_EQ(r.went_back, 1);
  EXPECT_EQ(r.dropped, 2);
  EXPECT_EQ(d.rows(), 4);
  EXPECT_DOUBLE_EQ(d["x"](2), 4.0);
  EXPECT_NE(r.Summary().find("dropping 2 rows"), std::string::npos);
}

}  // namespace
}  // namespace usvid
