// Straight running (methods/straight_running.h): the channels a port-starboard mirror turns over
// are zero there, the others at their medians, and a state the mirror turns over is read at plus
// and minus its RMS.
#include "methods/straight_running.h"

#include <gtest/gtest.h>

#include <cmath>

namespace usvid {
namespace {

TEST(StraightRunningTest, TheMirrorTurnsOverTheLateralChannelsOnly) {
  for (const char* c : {"v", "r", "delta", "nozzle", "tau_y", "tau_n", "wind_v", "current_v"})
    EXPECT_TRUE(MirrorTurnsOver(c)) << c;
  for (const char* c : {"u", "n", "rev", "throttle", "tau_x", "wind_u", "wind_speed", "U"})
    EXPECT_FALSE(MirrorTurnsOver(c)) << c;
}

TEST(StraightRunningTest, LevelsAreTheMedianAndTheRms) {
  const ChannelLevel level = LevelOf({3.0, -4.0, 1.0});
  EXPECT_EQ(level.median, 1.0);
  EXPECT_NEAR(level.rms, std::sqrt(26.0 / 3.0), 1e-12);
}

TEST(StraightRunningTest, PointsHoldTheLateralChannelsAtZero) {
  const std::vector<std::string> names = {"u", "v", "r", "delta", "n"};
  const std::vector<ChannelLevel> levels = {
      {7.0, 7.1}, {0.1, 0.3}, {0.01, 0.004}, {0.2, 0.3}, {1.5, 1.5}};
  const auto surge = StraightRunningPoints(names, levels, 0);
  ASSERT_EQ(surge.size(), 1u);
  EXPECT_EQ(surge[0], (std::vector<double>{7.0, 0.0, 0.0, 0.0, 1.5}));
  const auto yaw = StraightRunningPoints(names, levels, 2);
  ASSERT_EQ(yaw.size(), 2u);
  EXPECT_EQ(yaw[0], (std::vector<double>{7.0, 0.0, 0.004, 0.0, 1.5}));
  EXPECT_EQ(yaw[1], (std::vector<double>{7.0, 0.0, -0.004, 0.0, 1.5}));
}

}  // namespace
}  // namespace usvid
