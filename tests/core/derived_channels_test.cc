// Speed over ground and course from body velocities: U = |(u, v)|, chi = psi + atan2(v, u); the
// relative wind's body components, the air's velocity past the ship, from where it blows;
// existing channels are left as they are.
#include "core/derived_channels.h"

#include <gtest/gtest.h>

#include <cmath>

namespace usvid {
namespace {

class DerivedChannelsTest : public ::testing::Test {};

TEST_F(DerivedChannelsTest, SpeedAndCourseFromBodyVelocities) {
  Eigen::VectorXd t(2), u(2), v(2), psi(2);
  t << 0, 1;
  u << 3, 1;
  v << 4, -1;
  psi << 0.5, 0.0;
  Dataset d(t);
  d.Set("u", u);
  d.Set("v", v);
  d.Set("psi", psi);
  AddSpeedAndCourse(d);
  EXPECT_DOUBLE_EQ(d["U"](0), 5.0);
  EXPECT_DOUBLE_EQ(d["chi"](0), 0.5 + std::atan2(4.0, 3.0));
  EXPECT_DOUBLE_EQ(d["chi"](1), -M_PI / 4);
  // A measured U is kept.
  Dataset e(t);
  e.Set("u", u);
  e.Set("v", v);
  e.Set("U", Eigen::VectorXd::Constant(2, 7.0));
  AddSpeedAndCourse(e);
  EXPECT_EQ(e["U"](0), 7.0);
  EXPECT_FALSE(e.Has("chi"));  // no heading, no course
}

TEST_F(DerivedChannelsTest, WindComponentsAreTheAirsVelocityPastTheShip) {
  Eigen::VectorXd t(3), speed(3), from(3);
  t << 0, 1, 2;
  speed << 2, 3, 4;
  from << 0.0, M_PI / 2, std::nan("");  // from ahead, from starboard, a gap in the log
  Dataset d(t);
  d.Set("wind_speed", speed);
  d.Set("wind_direction", from, Eigen::Array<bool, 3, 1>(true, true, false));
  AddDerivedChannels(d);
  // From ahead, the air streams aft at the wind's speed; from starboard, towards port.
  EXPECT_DOUBLE_EQ(d["wind_u"](0), -2.0);
  EXPECT_NEAR(d["wind_v"](0), 0.0, 1e-15);
  EXPECT_NEAR(d["wind_u"](1), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(d["wind_v"](1), -3.0);
  // The pressure force's products: V^2 cos(gamma) = -V wind_u.
  EXPECT_DOUBLE_EQ(-speed(0) * d["wind_u"](0), 4.0);
  // A row whose direction was not logged has no components.
  EXPECT_FALSE(d.Get("wind_u").IsSampled(2));
  EXPECT_FALSE(d.Get("wind_v").IsSampled(2));
  EXPECT_FALSE(d.Has("U"));  // no body velocities, no speed
}

TEST_F(DerivedChannelsTest, ARecordWithoutWindGetsNoWindComponents) {
  Eigen::VectorXd t(2);
  t << 0, 1;
  Dataset d(t);
  d.Set("wind_speed", Eigen::VectorXd::Constant(2, 3.0));
  EXPECT_FALSE(CanDerive(d, "wind_u"));
  AddDerivedChannels(d);
  EXPECT_FALSE(d.Has("wind_u"));  // a speed alone has no direction
}

// CanDerive says beforehand what AddDerivedChannels will add, so a command can check its
// records' channels before it identifies.
TEST_F(DerivedChannelsTest, CanDeriveAgreesWithWhatIsAdded) {
  Eigen::VectorXd t(2);
  t << 0, 1;
  Dataset d(t);
  for (const char* c : {"u", "v", "wind_speed", "wind_direction"})
    d.Set(c, Eigen::VectorXd::Constant(2, 1.0));
  for (const char* c : {"U", "wind_u", "wind_v"}) EXPECT_TRUE(CanDerive(d, c)) << c;
  for (const char* c : {"chi", "r", "u"}) EXPECT_FALSE(CanDerive(d, c)) << c;  // u is logged
  AddDerivedChannels(d);
  for (const char* c : {"U", "wind_u", "wind_v"}) EXPECT_TRUE(d.Has(c)) << c;
  EXPECT_FALSE(d.Has("chi"));
  // What an error names when a channel is neither logged nor derivable.
  EXPECT_EQ(DerivedFrom("wind_u"), "wind_speed and wind_direction");
  EXPECT_EQ(DerivedFrom("chi"), "u, v and psi");
  EXPECT_EQ(DerivedFrom("r"), "");
}

}  // namespace
}  // namespace usvid
