// Speed over ground and course from body velocities: U = |(u, v)|, chi = psi + atan2(v, u);
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

}  // namespace
}  // namespace usvid
