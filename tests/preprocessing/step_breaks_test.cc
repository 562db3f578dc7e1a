// The spline's step breaks are kept where the inputs are piecewise constant; not made where an
// input ramps over several samples at its slew rate, nor where it is held; and dropped, and
// said, where they change every few samples (a quantised rpm, a hand-steered rudder): there the
// breaks would cut the record into pieces too short to differentiate (issue 38).
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

// A zig-zag's rudder: 0.5 s ramps between 9.5 s holds, the input changing by a fifth of its
// range at each of five samples in a row. A ramp is continuous, and so is x' = f: no breaks, and
// x' follows f. Breaking the spline at every sample of each ramp (before 2026-11-29) cut it into
// one-sample pieces there; on odin-hs's step grid, whose nozzle slews so, v' kept R^2 0.67
// against the noise-free record's, and now keeps 0.996 (docs/preprocessing.md).
TEST(StepBreaksTest, NoneWhereTheInputRampsOverSeveralSamples) {
  const auto rudder = [](int i) {
    const int phase = i % 100;
    const double sign = (i / 100) % 2 ? 1.0 : -1.0;
    return phase < 5 ? sign * (-1.0 + 0.4 * phase) : sign;
  };
  const Dataset d = Record(rudder);
  EXPECT_TRUE(StepBreaks({d["f"]}).empty());
  const PreparedData p = Preprocess(d, {"x"}, {"f"}, {});
  EXPECT_THAT(p.notes, Contains("derivatives by spline"));
  // x(i) sums f before sample i, so x' at sample i is f half a sample earlier: f(i - 1) and
  // f(i) averaged.
  const Eigen::VectorXd& f = d["f"];
  const Eigen::VectorXd& estimate = p.data["x_dot"];
  double error = 0.0;
  for (Eigen::Index i = 1; i < f.size(); ++i)
    error = std::max(error, std::abs(estimate(i) - 0.5 * (f(i - 1) + f(i))));
  EXPECT_LT(error, 0.1) << "the largest error of x' against f, whose range is 2";
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

// A quantised rpm that flips between two readings every third sample: each flip is a change over
// one sample, so a step, and the steps leave 0.3 s stretches.
TEST(StepBreaksTest, DroppedAndSaidWhereTheInputChangesEveryFewSamples) {
  const PreparedData p =
      Preprocess(Record([](int i) { return 91.7 + 0.1 * ((i / 3) % 2); }), {"x"}, {"f"}, {});
  EXPECT_THAT(p.notes, Contains(HasSubstr("no step breaks: the inputs' 333 changes")));
  EXPECT_THAT(p.notes, Contains("derivatives by spline"));
}

// A noisy or quantised input that changes at nearly every sample moves over several samples in
// a row, as a ramp does: no step.
TEST(StepBreaksTest, NoneWhereTheInputChangesAtEverySample) {
  const PreparedData p =
      Preprocess(Record([](int i) { return 91.7 + 0.1 * ((i * 7919) % 3 - 1); }), {"x"}, {"f"}, {});
  EXPECT_THAT(p.notes, Contains("derivatives by spline"));
}

}  // namespace
}  // namespace usvid
