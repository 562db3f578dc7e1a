// Logged disturbances (simulation/logged_disturbances.h), the measured track's records: the
// current in body axes turns with the heading; the logged relative wind is the true wind seen
// from the moving hull, at the gusts' speed of that instant; only what the conditions make can be
// logged, and the methods' extra inputs are named.
#include "simulation/logged_disturbances.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;

constexpr double kPi = std::numbers::pi;

// A record of three rows: the hull heading north, east, then south-west, with body velocities.
Dataset ThreeHeadings(double u, double v) {
  Dataset d(Eigen::Vector3d(0.0, 10.0, 20.0));
  d.Set("psi", Eigen::Vector3d(0.0, kPi / 2, 5 * kPi / 4));
  d.Set("u", Eigen::Vector3d::Constant(u));
  d.Set("v", Eigen::Vector3d::Constant(v));
  return d;
}

TEST(LoggedDisturbancesTest, TheCurrentInBodyAxesTurnsWithTheHeading) {
  Dataset d = ThreeHeadings(2.0, 0.0);
  EffectValues<double> e;
  e.current_north = 0.3;  // flowing north
  e.current_east = 0.0;
  const std::vector<std::string> added = LogDisturbances(d, {"current"}, nullptr, 1, e);
  EXPECT_EQ(added, (std::vector<std::string>{"current_u", "current_v"}));
  // Heading north: all of it along the course; heading east: the water moves north, to the
  // hull's port side (v is positive to starboard), so v_c < 0.
  EXPECT_NEAR(d["current_u"](0), 0.3, 1e-12);
  EXPECT_NEAR(d["current_v"](0), 0.0, 1e-12);
  EXPECT_NEAR(d["current_u"](1), 0.0, 1e-12);
  EXPECT_NEAR(d["current_v"](1), -0.3, 1e-12);
  // Heading south-west: against the bow quarter, its speed kept.
  EXPECT_NEAR(d["current_u"](2), -0.3 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(std::hypot(d["current_u"](2), d["current_v"](2)), 0.3, 1e-12);
}

// A 10 m/s wind from the north without gusts: from dead ahead at 12 m/s over a hull making
// 2 m/s north; over a hull making 2 m/s east, from port, 11.3 deg forward of the beam.
TEST(LoggedDisturbancesTest, TheLoggedWindIsTheTrueWindSeenFromTheMovingHull) {
  Dataset d = ThreeHeadings(2.0, 0.0);
  WindGusts g;
  g.wind = {10.0, 0.0, 0.0};
  const std::vector<std::string> added = LogDisturbances(d, {"wind"}, &g, 1, {});
  EXPECT_EQ(added, (std::vector<std::string>{"wind_speed", "wind_direction"}));
  EXPECT_NEAR(d["wind_speed"](0), 12.0, 1e-9);
  EXPECT_NEAR(std::remainder(d["wind_direction"](0), 2 * kPi), 0.0, 1e-9);
  EXPECT_NEAR(d["wind_speed"](1), std::sqrt(104.0), 1e-9);
  EXPECT_NEAR(d["wind_direction"](1), 1.5 * kPi + std::atan(0.2), 1e-9);
}

// At rest the anemometer reads the true wind: its speed is the gusts' at each row's time, and
// its direction the true one less the heading.
TEST(LoggedDisturbancesTest, TheLoggedWindCarriesTheGusts) {
  Dataset d = ThreeHeadings(0.0, 0.0);
  WindGusts g;
  g.wind = {8.0, kPi / 3, 0.3};
  LogDisturbances(d, {"wind"}, &g, 7, {});
  const GustySpeed speed(g.wind, 7);
  double spread = 0.0;
  for (Eigen::Index k = 0; k < 3; ++k) {
    EXPECT_NEAR(d["wind_speed"](k), speed(d.t()(k)), 1e-9);
    EXPECT_NEAR(std::remainder(d["wind_direction"](k) - (kPi / 3 - d["psi"](k)), 2 * kPi), 0.0,
                1e-9);
    spread = std::max(spread, std::abs(d["wind_speed"](k) - 8.0));
  }
  EXPECT_GT(spread, 1e-3) << "the gusts move the logged speed";
}

TEST(LoggedDisturbancesTest, OnlyWhatTheConditionsMakeCanBeLogged) {
  const std::vector<Effect> current = ParseEffects({"current=0.3"}, 1);
  EXPECT_NO_THROW(CheckLoggedDisturbances({"wind", "current"}, true, current, "s.json: logged"));
  const std::vector<std::pair<std::vector<std::string>, std::string>> bad = {
      {{"waves"}, "s.json: logged: 'waves' is no disturbance a record can log (wind, current)"},
      {{"wind"}, "'wind' logs the gusty wind, and no gusts are set"},
      {{"current", "current"}, "'current' is named twice"}};
  for (const auto& [items, message] : bad) {
    try {
      CheckLoggedDisturbances(items, false, current, "s.json: logged");
      ADD_FAILURE() << message;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr(message));
    }
  }
  EXPECT_THROW(CheckLoggedDisturbances({"current"}, true, {}, "x"), InputError);
  Dataset no_heading(Eigen::Vector3d(0.0, 1.0, 2.0));
  no_heading.Set("u", Eigen::Vector3d::Zero());
  EXPECT_THROW(LogDisturbances(no_heading, {"current"}, nullptr, 1, {}), InputError);
}

TEST(LoggedDisturbancesTest, NamesTheInputsAMethodReads) {
  EXPECT_EQ(LoggedInputChannels({"wind", "current"}),
            (std::vector<std::string>{"wind_speed", "wind_u", "wind_v", "current_u", "current_v"}));
  EXPECT_TRUE(LoggedInputChannels({}).empty());
}

}  // namespace
}  // namespace usvid
