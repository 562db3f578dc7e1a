// The spline's step breaks are kept where the inputs are piecewise constant, also where a
// rate-limited input ramps between long holds, and dropped, and said, where they change every
// few samples (a quantised rpm, a hand-steered rudder): there the breaks would cut the record
// into pieces too short to differentiate (issue 38).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>

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

TEST(StepBreaksTest, DroppedAndSaidWhereTheInputChangesEverySample) {
  const PreparedData p =
      Preprocess(Record([](int i) { return 91.7 + 0.1 * ((i * 7919) % 3 - 1); }), {"x"}, {"f"}, {});
  EXPECT_THAT(p.notes, Contains(HasSubstr("no step breaks: the inputs' ")));
  EXPECT_THAT(p.notes, Contains("derivatives by spline"));
}

}  // namespace
}  // namespace usvid
