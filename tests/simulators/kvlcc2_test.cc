// Vessel kvlcc2 (docs/vessels/kvlcc2.md), the MMG standard model with Yasukawa & Yoshimura's
// (2015) KVLCC2 coefficients: the straight-run speed where propeller thrust meets resistance,
// the ITTC rudder sign of the MARIN data, a 35 deg turning circle of tanker size, and the
// current acting on the relative velocity only.
#include "simulators/kvlcc2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "simulators/rk4.h"

namespace usvid {
namespace {

using State = StateVector<double, Kvlcc2::kStates>;
using Input = std::array<double, Kvlcc2::kInputs>;
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kTestRpm = 91.7;  // the MARIN free-running tests, full scale
constexpr auto& kP = Kvlcc2::kDefaultParams;

State Hold(State x, const Input& in, double seconds, const Environment<double>& env = {}) {
  const auto f = [&](const double* s, double* d) {
    Kvlcc2::Derivative(s, in.data(), kP.data(), env, d);
  };
  for (long i = 0; i < std::lround(seconds / 0.5); ++i) Rk4Step<double, Kvlcc2::kStates>(f, 0.5, x);
  return x;
}

State Straight(const Environment<double>& env = {}) {
  State x = State::Zero();
  x(3) = 7.0;
  return Hold(x, {0.0, kTestRpm}, 6000.0, env);
}

// At 91.7 rpm the model settles where (1 - t_P) T = R_0' q L d u^2. With the model-scale R_0'
// and w_P0 of the 7 m model that is 13.5 kn, not the 15.8 kn of the tests (docs: the surge
// balance is the nominal model's first error on the MARIN data).
TEST(Kvlcc2Test, StraightRunSettlesWhereThrustMeetsResistance) {
  const State x = Straight();
  const double u = x(3);
  EXPECT_NEAR(u / 0.5144, 13.5, 0.3);
  EXPECT_NEAR(x(4), 0.0, 1e-9);
  EXPECT_NEAR(x(5), 0.0, 1e-12);
  // The balance by hand: J_P, K_T and the thrust of the propeller against hull resistance.
  const double n = kTestRpm / 60.0, D = Kvlcc2::kPropellerDiameter;
  const double J = u * (1 - kP[Kvlcc2::kWP0]) / (n * D);
  const double kt = kP[Kvlcc2::kK0] + kP[Kvlcc2::kK1] * J + kP[Kvlcc2::kK2] * J * J;
  const double thrust = (1 - kP[Kvlcc2::kTP]) * Kvlcc2::kRho * n * n * std::pow(D, 4) * kt;
  const double resistance =
      kP[Kvlcc2::kR0] * 0.5 * Kvlcc2::kRho * Kvlcc2::kLength * Kvlcc2::kDraft * u * u;
  EXPECT_NEAR(thrust / resistance, 1.0, 1e-4);
}

// ITTC sign, as in the MARIN files: positive delta turns to port (r < 0), negative to starboard.
// The hull is symmetric; only the flow-straightening gamma_R and the wake's C_2 differ by side,
// so the steady turns differ by a little.
TEST(Kvlcc2Test, PositiveRudderTurnsToPortAndTurnsAreNearlySymmetric) {
  const State x0 = Straight();
  const State port = Hold(x0, {20 * kDeg, kTestRpm}, 1500.0);
  const State starboard = Hold(x0, {-20 * kDeg, kTestRpm}, 1500.0);
  EXPECT_LT(port(5), 0.0);
  EXPECT_GT(starboard(5), 0.0);
  EXPECT_NEAR(port(5) / starboard(5), -1.0, 0.1);
  // Speed lost in the turn: a full-form tanker loses about half of it at 20 deg.
  EXPECT_LT(starboard(3), 0.75 * x0(3));
  EXPECT_GT(starboard(3), 0.3 * x0(3));
}

// The 35 deg turning circle of a full-form tanker: tactical diameter about 3 ship lengths
// (SIMMAN measured about 3.3 Lpp; MMG predictions 3.0-3.4 Lpp), reached as the heading changes
// by 180 deg, with the rudder at its 2.32 deg/s.
TEST(Kvlcc2Test, TurningCircleHasTankerTacticalDiameter) {
  State x = Straight();
  x(0) = x(1) = x(2) = 0.0;
  double delta = 0.0, tactical = -1.0;
  for (double t = 0; t < 3000.0 && tactical < 0; t += 0.5) {
    delta = std::max(-35 * kDeg, delta - Kvlcc2::kYawRateLimit * 0.5);
    x = Hold(x, {delta, kTestRpm}, 0.5);
    if (x(2) >= std::numbers::pi) tactical = x(1);
  }
  ASSERT_GT(tactical, 0.0);
  EXPECT_GT(tactical / Kvlcc2::kLength, 2.6);
  EXPECT_LT(tactical / Kvlcc2::kLength, 3.8);
}

// A uniform current carries the ship: the motion through the water is the calm-water one, and
// over ground the current adds (heading north, a 1 m/s current to the north: u grows by 1).
TEST(Kvlcc2Test, CurrentActsOnRelativeVelocity) {
  const State calm = Straight();
  const State carried = Straight({1.0, 0.0});
  EXPECT_NEAR(carried(3) - calm(3), 1.0, 1e-6);
  EXPECT_NEAR(carried(4), 0.0, 1e-9);
}

}  // namespace
}  // namespace usvid
