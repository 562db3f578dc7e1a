// Decimation for display: gaps at non-finite points, at most four points per pixel column,
// extremes and order kept, short series untouched.
#include "plot/decimate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace usvid::svg {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

class DecimateTest : public ::testing::Test {
 protected:
  AxisMap identity_{0.0, 1.0};
};

// Points in distinct pixel columns are all kept, in order.
TEST_F(DecimateTest, ShortSeriesIsUnchanged) {
  const std::vector<double> x = {0, 1, 2, 3};
  const std::vector<double> y = {5, 1, 4, 2};
  const auto lines = ToPolylines(x, y, identity_, identity_);
  ASSERT_EQ(lines.size(), 1u);
  ASSERT_EQ(lines[0].size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(lines[0][i].x, x[i]);
    EXPECT_EQ(lines[0][i].y, y[i]);
  }
}

// NaN and infinite values split the series; a leading or trailing gap leaves no empty line.
TEST_F(DecimateTest, NonFiniteValuesSplitTheSeries) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> x = {0, 1, 2, 3, 4, 5, kNaN, 7};
  const std::vector<double> y = {kNaN, 1, 2, inf, 4, 5, 6, 7};
  const auto lines = ToPolylines(x, y, identity_, identity_);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].size(), 2u);
  EXPECT_EQ(lines[1].size(), 2u);
  EXPECT_EQ(lines[2].size(), 1u);
}

// 100k samples over 1000 px keep at most four per column, including the single-sample spike
// and dip, and stay ordered in x.
TEST_F(DecimateTest, LongSeriesKeepsExtremesPerColumn) {
  const int n = 100000;
  std::vector<double> x(n);
  std::vector<double> y(n);
  for (int i = 0; i < n; ++i) {
    x[i] = i;
    y[i] = std::sin(i * 0.01);
  }
  y[4242] = 50.0;
  y[90001] = -30.0;
  const AxisMap to_px{0.0, 1000.0 / n};
  const auto lines = ToPolylines(x, y, to_px, identity_);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_LE(lines[0].size(), 4000u);
  EXPECT_GE(lines[0].size(), 1000u);
  const auto [lo, hi] = std::minmax_element(lines[0].begin(), lines[0].end(),
                                            [](const auto& a, const auto& b) { return a.y < b.y; });
  EXPECT_EQ(lo->y, -30.0);
  EXPECT_EQ(hi->y, 50.0);
  EXPECT_TRUE(std::is_sorted(lines[0].begin(), lines[0].end(),
                             [](const auto& a, const auto& b) { return a.x < b.x; }));
  EXPECT_EQ(lines[0].front().x, 0.0);
  EXPECT_DOUBLE_EQ(lines[0].back().x, (n - 1) * 1000.0 / n);
}

// Far-off values are limited to kPixelLimit instead of producing huge coordinates.
TEST_F(DecimateTest, PixelCoordinatesAreLimited) {
  const std::vector<double> x = {0, 1};
  const std::vector<double> y = {1e300, -1e300};
  const auto lines = ToPolylines(x, y, identity_, identity_);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0][0].y, kPixelLimit);
  EXPECT_EQ(lines[0][1].y, -kPixelLimit);
}

}  // namespace
}  // namespace usvid::svg
