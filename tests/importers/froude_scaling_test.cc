// Froude scaling: each dimension's factor, derivatives per second, and refusals before any change.
#include "importers/froude_scaling.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"

namespace usvid {
namespace {

Dataset Record() {
  Dataset d(Eigen::Vector2d(0.0, 1.0));
  for (const char* name : {"north", "u", "r", "n", "psi", "tau_x", "tau_n", "u_dot", "r_dot"})
    d.Set(name, Eigen::Vector2d(1.0, 2.0));
  return d;
}

// At the same Froude number a 4x longer ship is 2x faster, turns 2x slower and runs 2x longer;
// forces go with the displaced volume (64x), moments with one more length (256x).
TEST(FroudeScalingTest, EachDimensionScalesByItsLaw) {
  Dataset d = Record();
  const auto scaled = FroudeScale(d, 4.0);
  EXPECT_DOUBLE_EQ(d.t()(1), 2.0);
  EXPECT_DOUBLE_EQ(d["north"](1), 8.0);
  EXPECT_DOUBLE_EQ(d["u"](1), 4.0);
  EXPECT_DOUBLE_EQ(d["r"](1), 1.0);
  EXPECT_DOUBLE_EQ(d["n"](1), 1.0);
  EXPECT_DOUBLE_EQ(d["psi"](1), 2.0);
  EXPECT_DOUBLE_EQ(d["tau_x"](1), 128.0);
  EXPECT_DOUBLE_EQ(d["tau_n"](1), 512.0);
  EXPECT_DOUBLE_EQ(d["u_dot"](1), 2.0);  // an acceleration keeps its value
  EXPECT_DOUBLE_EQ(d["r_dot"](1), 0.5);
  ASSERT_EQ(scaled.size(), 9u);
  EXPECT_EQ(scaled[7].dimension, "speed per second");
}

// The importers' extra channels scale without --dimension: MARIN's roll phi and roll rate p,
// HSVA's roll, thrust and torque (so `usvid import --format marin-dat|hsva-dat --scale` works).
TEST(FroudeScalingTest, ImportersExtrasHaveTheirDimensions) {
  Dataset d(Eigen::Vector2d(0.0, 1.0));
  for (const char* name : {"phi", "p", "thrust", "torque", "rev"})
    d.Set(name, Eigen::Vector2d(1.0, 2.0));
  FroudeScale(d, 4.0);
  EXPECT_DOUBLE_EQ(d["phi"](1), 2.0);
  EXPECT_DOUBLE_EQ(d["p"](1), 1.0);
  EXPECT_DOUBLE_EQ(d["thrust"](1), 128.0);
  EXPECT_DOUBLE_EQ(d["torque"](1), 512.0);
  EXPECT_DOUBLE_EQ(d["rev"](1), 1.0);  // revolutions per time
}

// Scaling there and back restores the record.
TEST(FroudeScalingTest, BackAndForthIsIdentity) {
  Dataset d = Record();
  FroudeScale(d, 37.5);
  FroudeScale(d, 1.0 / 37.5);
  const Dataset original = Record();
  EXPECT_NEAR(d.t()(1), 1.0, 1e-14);
  for (const Channel& c : original.channels())
    EXPECT_NEAR(d[c.name](1), c.Value(1), 1e-12) << c.name;
}

// A bad scale or an unknown channel fails before anything changes.
TEST(FroudeScalingTest, RefusesBeforeChanging) {
  Dataset d = Record();
  for (double lambda : {0.0, -1.0, std::nan("")}) EXPECT_THROW(FroudeScale(d, lambda), InputError);
  d.Set("gust", Eigen::Vector2d(1.0, 1.0));
  try {
    FroudeScale(d, 4.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("channel 'gust' has no known dimension"));
  }
  EXPECT_DOUBLE_EQ(d["u"](1), 2.0);
  FroudeScale(d, 4.0, {{"gust", ParseDimension("speed")}});
  EXPECT_DOUBLE_EQ(d["gust"](1), 2.0);
  EXPECT_THROW(ParseDimension("furlong"), InputError);
  EXPECT_THROW(FroudeScale(d, 4.0, {{"nope", Dimension::kSpeed}}), InputError);
}

}  // namespace
}  // namespace usvid
