// Nice axis ticks: 1-2-5 steps, limits that cover the data, a bounded tick count, and compact
// labels without floating-point noise.
#include "plot/axis_ticks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

namespace usvid::svg {
namespace {

class AxisTicksTest : public ::testing::Test {
 protected:
  static bool IsNiceStep(double step) {
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    return std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
           std::abs(mantissa - 5) < 1e-9;
  }
};

// For ranges of every scale and sign the limits cover the data, are ticks themselves, the step
// is 1, 2 or 5 times a power of ten and the count stays within the budget.
TEST_F(AxisTicksTest, NiceTicksCoverTheDataWithOneTwoFiveSteps) {
  for (const auto& [lo, hi, budget] : {std::tuple{0.13, 7.9, 6},
                                       {-0.37, 2.71, 8},
                                       {1e-5, 3.2e-5, 5},
                                       {-12000.0, -3.0, 7},
                                       {99.5, 100.5, 6},
                                       {0.0, 1e7, 6},
                                       {-1.0, 1.0, 3},
                                       {0.5, 1.5, 2}}) {
    const AxisTicks t = NiceTicks(lo, hi, budget);
    EXPECT_LE(t.lo, lo);
    EXPECT_GE(t.hi, hi);
    EXPECT_TRUE(IsNiceStep(t.step)) << t.step;
    EXPECT_LE(static_cast<int>(t.values.size()), budget);
    EXPECT_GE(t.values.size(), 2u);
    EXPECT_DOUBLE_EQ(t.values.front(), t.lo);
    EXPECT_DOUBLE_EQ(t.values.back(), t.hi);
    for (std::size_t i = 1; i < t.values.size(); ++i) {
      EXPECT_NEAR(t.values[i] - t.values[i - 1], t.step, 1e-9 * t.step);
    }
    EXPECT_EQ(t.labels.size(), t.values.size());
  }
}

// The finest step within the budget is chosen: 0..10 with 6 ticks steps by 2.
TEST_F(AxisTicksTest, NiceTicksUseTheFinestStepThatFits) {
  const AxisTicks t = NiceTicks(0.0, 10.0, 6);
  EXPECT_DOUBLE_EQ(t.step, 2.0);
  EXPECT_EQ(t.labels, (std::vector<std::string>{"0", "2", "4", "6", "8", "10"}));
}

// Fixed limits are kept; the ticks fall on nice multiples inside them.
TEST_F(AxisTicksTest, FixedTicksKeepTheLimits) {
  const AxisTicks t = FixedTicks(-0.33, 1.07, 8);
  EXPECT_DOUBLE_EQ(t.lo, -0.33);
  EXPECT_DOUBLE_EQ(t.hi, 1.07);
  EXPECT_DOUBLE_EQ(t.step, 0.2);
  EXPECT_EQ(t.labels,
            (std::vector<std::string>{"\u22120.2", "0", "0.2", "0.4", "0.6", "0.8", "1.0"}));
}

// A constant signal gets a range around its value instead of a zero-width axis.
TEST_F(AxisTicksTest, DegenerateRangeIsWidened) {
  const AxisTicks zero = NiceTicks(0.0, 0.0, 5);
  EXPECT_LT(zero.lo, 0.0);
  EXPECT_GT(zero.hi, 0.0);
  const AxisTicks three = NiceTicks(3.0, 3.0, 5);
  EXPECT_LT(three.lo, 3.0);
  EXPECT_GT(three.hi, 3.0);
}

// Labels carry just the decimals the step needs, no binary noise, a typographic minus, and
// scientific notation for very large or small axes.
TEST_F(AxisTicksTest, LabelsAreCompact) {
  EXPECT_EQ(FormatTick(0.1 + 0.2, 0.1, 1.0), "0.3");
  EXPECT_EQ(FormatTick(0.25, 0.05, 1.0), "0.25");
  EXPECT_EQ(FormatTick(-2.0, 1.0, 5.0), "\u22122");
  EXPECT_EQ(FormatTick(1e-17, 0.2, 1.0), "0");
  EXPECT_EQ(FormatTick(2e6, 1e6, 5e6), "2e6");
  EXPECT_EQ(FormatTick(1.5e6, 5e5, 5e6), "1.5e6");
  EXPECT_EQ(FormatTick(4e-4, 2e-4, 8e-4), "4e-4");
  EXPECT_EQ(FormatTick(12000, 2000, 20000), "12000");
}

}  // namespace
}  // namespace usvid::svg
