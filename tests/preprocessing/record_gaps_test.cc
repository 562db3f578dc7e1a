// Preprocessing never bridges a gap (issue 38): records joined for one fit (core/records.h) and
// a dropout inside one record are smoothed and differentiated each on its own, the grid keeps
// the gap, and an input shifted by the delay restarts at each stretch's first value.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/records.h"
#include "core/stretches.h"
#include "preprocessing/pipeline.h"

namespace usvid {
namespace {

using ::testing::Contains;
using ::testing::HasSubstr;

// x(t) and the input f(t), sampled at 10 Hz over [0, seconds].
Dataset Record(double seconds, const std::function<double(double)>& x,
               const std::function<double(double)>& f) {
  const auto n = static_cast<Eigen::Index>(std::lround(seconds * 10)) + 1;
  Dataset d(Eigen::VectorXd::LinSpaced(n, 0.0, seconds));
  Eigen::VectorXd xs(n), fs(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    xs(k) = x(d.t()(k));
    fs(k) = f(d.t()(k));
  }
  d.Set("x", xs);
  d.Set("f", fs);
  return d;
}

TEST(RecordGapsTest, JoinedRecordsAreDifferentiatedEachOnItsOwn) {
  // x rises at 2/s in the first record and falls at 3/s from 100 in the second: a spline
  // across the join would bend both ends towards the jump between them.
  const Dataset joined =
      JoinRecords({Record(
                       20, [](double t) { return 2 * t; }, [](double) { return 1.0; }),
                   Record(
                       20, [](double t) { return 100 - 3 * t; }, [](double) { return -1.0; })});
  const PreparedData p = Preprocess(joined, {"x"}, {"f"}, {});
  EXPECT_THAT(p.notes, Contains(HasSubstr("2 stretches between gaps or records")));
  const std::vector<Stretch> s = Stretches(p.data.t(), kGridGapFactor);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].rows(), 201);
  EXPECT_EQ(s[1].rows(), 201);
  const Eigen::VectorXd& xdot = p.data["x_dot"];
  EXPECT_NEAR(xdot(s[0].end - 1), 2.0, 1e-6);  // the first record's last row
  EXPECT_NEAR(xdot(s[1].first), -3.0, 1e-6);   // the second's first
  EXPECT_EQ(p.data["f"](s[1].first), -1.0);
}

TEST(RecordGapsTest, ADropoutInsideARecordIsNotBridged) {
  // x = sin(t) with a dropout of every channel from 9.9 s to 12.1 s.
  Dataset d = Record(
      30, [](double t) { return std::sin(t); }, [](double) { return 0.0; });
  std::vector<bool> keep(d.rows());
  for (Eigen::Index k = 0; k < d.rows(); ++k) keep[k] = d.t()(k) < 9.95 || d.t()(k) > 12.05;
  d.KeepRows(keep);
  // Where the dropout was, the function jumps: a bridge would show in the derivative.
  Eigen::VectorXd x = d["x"];
  for (Eigen::Index k = 0; k < d.rows(); ++k)
    if (d.t()(k) > 12.0) x(k) += 5.0;
  d.Set("x", x);
  const PreparedData p = Preprocess(d, {"x"}, {"f"}, {});
  const std::vector<Stretch> s = Stretches(p.data.t(), kGridGapFactor);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_NEAR(p.data.t()(s[0].end - 1), 9.9, 1e-9);
  EXPECT_NEAR(p.data.t()(s[1].first), 12.1, 1e-9);
  for (const Eigen::Index k : {s[0].end - 1, s[1].first})
    EXPECT_NEAR(p.data["x_dot"](k), std::cos(p.data.t()(k)), 0.02) << "at t = " << p.data.t()(k);
}

TEST(RecordGapsTest, ADelayedInputRestartsAfterTheJoin) {
  const Dataset joined =
      JoinRecords({Record(
                       20, [](double t) { return t; }, [](double) { return 1.0; }),
                   Record(
                       20, [](double t) { return t; }, [](double) { return 7.0; })});
  PreprocessOptions o;
  o.delay_s = 0.5;
  const PreparedData p = Preprocess(joined, {"x"}, {"f"}, o);
  const std::vector<Stretch> s = Stretches(p.data.t(), kGridGapFactor);
  ASSERT_EQ(s.size(), 2u);
  for (Eigen::Index k = s[1].first; k < s[1].first + 5; ++k)
    EXPECT_EQ(p.data["f"](k), 7.0);  // not the first record's 1.0
}

}  // namespace
}  // namespace usvid
