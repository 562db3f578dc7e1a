// Where a test's record ends (preprocessing/record_end.h): a log that idles its propeller, runs
// it, stops it and goes on recording the recovery ends at the propeller's last running row; a
// noisy zero reads as stopped; a log that runs to its last row loses nothing; a channel that is
// missing or never runs is refused, naming it.
#include "preprocessing/record_end.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/dataset.h"
#include "core/error.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;

// 10 Hz: idle at 1.67 rps for 20 s, 16.7 rps until `stop_s`, then `after` until 140 s, while the
// yaw rate swings (the recovery's thrusters).
Dataset Trial(double stop_s, double after) {
  constexpr int kN = 1401;
  Eigen::VectorXd t(kN), n(kN), r(kN);
  for (int i = 0; i < kN; ++i) {
    t(i) = 0.1 * i;
    n(i) = t(i) < 20.0 ? 1.67 : t(i) <= stop_s ? 16.7 : after;
    r(i) = t(i) <= stop_s ? 0.05 : 0.1 * std::sin(2.0 * t(i));
  }
  Dataset d(t);
  d.Set("n", n);
  d.Set("r", r);
  return d;
}

TEST(RecordEndTest, EndsAtThePropellersLastRunningRow) {
  Dataset d = Trial(127.0, 0.0);
  const RecordEnd end = EndAtStop(d, "n");
  EXPECT_DOUBLE_EQ(end.t_end, 127.0);
  EXPECT_EQ(end.dropped_rows, 130);
  EXPECT_NEAR(end.dropped_s, 13.0, 1e-9);
  ASSERT_EQ(d.rows(), 1271);
  EXPECT_DOUBLE_EQ(d.t()(d.rows() - 1), 127.0);
  EXPECT_DOUBLE_EQ(d["r"](d.rows() - 1), 0.05);  // the test's, not the recovery's
  EXPECT_THAT(DescribeRecordEnd(end, "n"),
              HasSubstr("ended where n stopped, at t = 127.0 s: 13.0 s (130 rows) dropped"));
}

TEST(RecordEndTest, ANoisyZeroIsStoppedAndARunToTheEndLosesNothing) {
  Dataset noisy = Trial(127.0, 0.05);  // 0.3 % of 16.7 rps
  EXPECT_EQ(EndAtStop(noisy, "n").dropped_rows, 130);
  Dataset running = Trial(200.0, 0.0);
  EXPECT_EQ(EndAtStop(running, "n").dropped_rows, 0);
  EXPECT_EQ(running.rows(), 1401);
}

TEST(RecordEndTest, AMissingOrIdleChannelIsRefused) {
  Dataset d = Trial(127.0, 0.0);
  try {
    EndAtStop(d, "rpm");
    FAIL() << "a missing channel was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("no column 'rpm'"));
  }
  d.Set("n", Eigen::VectorXd::Zero(d.rows()));
  try {
    EndAtStop(d, "n");
    FAIL() << "a channel that never runs was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("'n' never runs"));
  }
  EXPECT_EQ(d.rows(), 1401);  // nothing lost
}

}  // namespace
}  // namespace usvid
