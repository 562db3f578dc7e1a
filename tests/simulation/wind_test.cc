// The wind on a ship (simulators/wind_force.h, simulation/wind_estimates.h,
// maneuvers/true_wind.h; docs/model.md#wind): Fujiwara et al. 1998's coefficients for the Esso
// Osaka model push it the way the wind blows, mirror between the two sides, and grow with the
// square of the relative speed; the relative wind aboard is the true wind less the ship's own
// velocity, counted from the bow.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <numbers>

#include "maneuvers/true_wind.h"
#include "simulation/wind_estimates.h"
#include "simulators/wind_force.h"

namespace usvid {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The Esso Osaka model's body above the water (Miyauchi et al. 2022's simulator).
WindBody Esso() {
  WindBody b;
  b.L = 3.0, b.B = 0.48925, b.A_T = 0.13544, b.A_L = 0.52038, b.A_OD = 0.1423;
  b.C = -0.01299, b.C_BR = -0.06209, b.H_BR = 0.294, b.H_C = 0.10359;
  return b;
}

std::array<double, WindCoefficients::kCount> Coefficients(const WindBody& body) {
  std::array<double, WindCoefficients::kCount> c{};
  const std::vector<MmgEstimate> e = EstimateWindCoefficients(body);
  EXPECT_EQ(e.size(), c.size());
  for (size_t i = 0; i < e.size(); ++i) {
    EXPECT_EQ(e[i].name, WindCoefficients::kNames[i]);
    c[i] = e[i].value;
  }
  return c;
}

// [X, Y, N] of a wind of `speed` from `from_deg` relative to the bow.
std::array<double, 3> Force(double speed, double from_deg) {
  const WindBody b = Esso();
  const auto c = Coefficients(b);
  std::array<double, 3> f{};
  AddWindForce(speed, from_deg * kDeg, c.data(), WindAreas{1.22, b.A_T, b.A_L, b.L}, 1.0, f.data());
  return f;
}

TEST(WindTest, TheWindPushesTheShipTheWayItBlows) {
  // A head wind pushes astern and turns nothing; a following wind pushes ahead.
  const auto head = Force(2.0, 0.0), stern = Force(2.0, 180.0);
  EXPECT_LT(head[0], 0.0);
  EXPECT_NEAR(head[1], 0.0, 1e-12);
  EXPECT_NEAR(head[2], 0.0, 1e-12);
  EXPECT_GT(stern[0], 0.0);
  // From starboard (90 deg) to port (negative Y); from port to starboard.
  EXPECT_LT(Force(2.0, 90.0)[1], 0.0);
  EXPECT_GT(Force(2.0, 270.0)[1], 0.0);
  // A beam wind's side force on a tanker's profile: C_Y about 1 (Fujiwara's tankers 0.8-1.1),
  // over q A_L.
  const double q = 0.5 * 1.22 * 2.0 * 2.0;
  EXPECT_NEAR(-Force(2.0, 90.0)[1] / (q * Esso().A_L), 1.0, 0.15);
  // A head wind's drag over q A_T: 0.5-0.9 for merchant ships.
  EXPECT_GT(-head[0] / (q * Esso().A_T), 0.5);
  EXPECT_LT(-head[0] / (q * Esso().A_T), 0.9);
}

TEST(WindTest, TheSidesMirrorAndTheForceGrowsWithTheSquareOfTheSpeed) {
  for (double from : {20.0, 60.0, 110.0, 150.0}) {
    const auto starboard = Force(3.0, from), port = Force(3.0, 360.0 - from);
    EXPECT_NEAR(starboard[0], port[0], 1e-12) << from;
    EXPECT_NEAR(starboard[1], -port[1], 1e-12) << from;
    EXPECT_NEAR(starboard[2], -port[2], 1e-12) << from;
    const auto twice = Force(6.0, from);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(twice[i], 4.0 * starboard[i], 1e-9) << from;
  }
  // No areas, or no wind: nothing.
  const auto c = Coefficients(Esso());
  std::array<double, 3> f{};
  AddWindForce(5.0, 1.0, c.data(), WindAreas{1.22, 0.0, 0.0, 3.0}, 1.0, f.data());
  AddWindForce(0.0, 1.0, c.data(), WindAreas{1.22, 0.1, 0.5, 3.0}, 1.0, f.data());
  EXPECT_EQ(f, (std::array<double, 3>{0.0, 0.0, 0.0}));
}

TEST(WindTest, TheRelativeWindIsTheTrueWindLessTheShipsVelocity) {
  // Calm, at 0.5 m/s ahead: a head wind of 0.5 m/s.
  auto rel = RelativeWind(0.0, 0.0, 0.3, 0.5, 0.0);
  EXPECT_NEAR(rel[0], 0.5, 1e-12);
  EXPECT_NEAR(rel[1], 0.0, 1e-12);
  // At rest heading north, a wind from the east comes from starboard (90 deg); heading east, a
  // wind from the north comes from port (270 deg).
  rel = RelativeWind(2.0, 90.0 * kDeg, 0.0, 0.0, 0.0);
  EXPECT_NEAR(rel[0], 2.0, 1e-12);
  EXPECT_NEAR(rel[1], 90.0 * kDeg, 1e-12);
  rel = RelativeWind(2.0, 0.0, 90.0 * kDeg, 0.0, 0.0);
  EXPECT_NEAR(rel[1], 270.0 * kDeg, 1e-12);
  // A beam wind of 1 m/s on a ship at 1 m/s: 1.41 m/s from 45 deg.
  rel = RelativeWind(1.0, 90.0 * kDeg, 0.0, 1.0, 0.0);
  EXPECT_NEAR(rel[0], std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(rel[1], 45.0 * kDeg, 1e-12);
}

// What a log's relative wind says of the true wind: the air over the ground, from which any
// hull's own relative wind follows again (maneuvers/true_wind.h, AirOverGround).
TEST(WindTest, TheAirOverTheGroundIsTheRelativeWindPlusTheShipsVelocity) {
  // A wind from the east (it blows west) over a ship heading north at 1 m/s: 1.41 m/s from
  // 45 deg aboard.
  std::array<double, 2> air = AirOverGround(std::sqrt(2.0), 45.0 * kDeg, 0.0, 1.0, 0.0);
  EXPECT_NEAR(air[0], 0.0, 1e-12);
  EXPECT_NEAR(air[1], -1.0, 1e-12);
  // Any true wind, heading and velocity: the relative wind read aboard gives the true wind back.
  for (const double from : {10.0, 100.0, 200.0, 330.0})
    for (const double psi : {-2.0, 0.4, 3.0}) {
      const std::array<double, 2> rel = RelativeWind(1.7, from * kDeg, psi, 0.3, -0.1);
      air = AirOverGround(rel[0], rel[1], psi, 0.3, -0.1);
      EXPECT_NEAR(std::hypot(air[0], air[1]), 1.7, 1e-12);
      const std::array<double, 2> again = RelativeWindOf(air, psi + 0.5, 0.2, 0.05);
      const std::array<double, 2> expected = RelativeWind(1.7, from * kDeg, psi + 0.5, 0.2, 0.05);
      EXPECT_NEAR(again[0], expected[0], 1e-12);
      EXPECT_NEAR(again[1], expected[1], 1e-12);
    }
}

}  // namespace
}  // namespace usvid
