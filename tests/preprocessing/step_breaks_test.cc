// The spline's step breaks are kept where the inputs are piecewise constant, also where a
// rate-limited input ramps between long holds, and dropped, and said, where they change every
// few samples (a quantised rpm, a hand-steered rudder): there the breaks would cut the record
// into pieces too short to differentiate (issue 38).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>

#include "preprocessing/derivative.h"
#include "preprocessing/pipeline.h"

namespace usvid {
namespace {

using ::testing::Contains;
using ::testing::HasSubstr;

// x' = f, sampled at 10 Hz for 100 s, under the input f.
Dataset Record(const std::function<double(int)>& f) {
  const int n = 1001;
  Dataset d(Eigen::VectorXd::LinSpaced(n, 0.0, 100.0));
  Eigen::VectorXd x(n), u(n);
  double state = 0.0;
  for (int i = 0; i < n; ++i) {
    u(i) = f(i);
    x(i) = state;
    state += 0.1 * u(i);
  }
  d.Set("x", x);
  d.Set("f", u);
  return d;
}

TEST(StepBreaksTest, KeptForPiecewiseConstantInputs) {
  const PreparedData p =
      Preprocess(Record([](int i) { return (i / 50) % 2 ? 1.0 : -1.0; }), {"x"}, {"f"}, {});
  EXPECT_THAT(p.notes, Contains(HasSubstr("with 20 step breaks")));
}

// A zig-zag's rudder: 0.5 s ramps (a break at every sample) between 9.5 s holds.
TEST(StepBreaksTest, KeptForRampsBetweenLongHolds) {
  const PreparedData p = Preprocess(Record([](int i) {
                                      const int phase = i % 100;
                                      const double sign = (i / 100) % 2 ? 1.0 : -1.0;
                                      return phase < 5 ? sign * (-1.0 + 0.4 * phase) : sign;
                                    }),
                                    {"x"}, {"f"}, {});
  EXPECT_THAT(p.notes, Contains(HasSubstr("step breaks")));
  EXPECT_THAT(p.notes, ::testing::Not(Contains(HasSubstr("no step breaks"))));
}

// A held propeller beside the stepping input: 91.7 rpm, as resampling by a cubic spline gives it
// back, off by rounding (up to 1.4e-14). Its range is rounding, so it has no steps; as a fraction
// of that range every rounding was one, and the breaks cut the simulated KVLCC2's zig-zag into
// 2 s pieces whose r' kept 4 % of the true derivative's variance (issue 38).
TEST(StepBreaksTest, NoneForAnInputHeldConstantUpToRounding) {
  Dataset d = Record([](int i) { return (i / 50) % 2 ? 1.0 : -1.0; });
  Eigen::VectorXd rev(d.rows());
  for (Eigen::Index i = 0; i < rev.size(); ++i)
    rev(i) = 91.7 + 1.4e-14 * static_cast<double>(i % 3);
  ASSERT_GT(rev.maxCoeff(), rev.minCoeff());
  EXPECT_TRUE(StepBreaks({rev}).empty());
  EXPECT_EQ(StepBreaks({d["f"], rev}).size(), 20u);
  d.Set("rev", rev);
  const PreparedData p = Preprocess(d, {"x"}, {"f", "rev"}, {});
  EXPECT_THAT(p.notes, Contains(HasSubstr("with 20 step breaks")));
}

TEST(StepBreaksTest, DroppedAndSaidWhereTheInputChangesEverySample) {
  const PreparedData p =
      Preprocess(Record([](int i) { return 91.7 + 0.1 * ((i * 7919) % 3 - 1); }), {"x"}, {"f"}, {});
  EXPECT_THAT(p.notes, Contains(HasSubstr("no step breaks: the inputs' ")));
  EXPECT_THAT(p.notes, Contains("derivatives by spline"));
}

}  // namespace
}  // namespace usvid
