// Vessel odin-hs (docs/vessels/odin-hs.md): resistance across the regimes, steady speeds, top
// speed, turning, actuators, bounded response to any admissible input, and Jet derivatives.
#include "simulators/odin_hs.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "simulators/rk4.h"

namespace usvid {
namespace {

using State = StateVector<double, OdinHs::kStates>;
using Input = std::array<double, OdinHs::kInputs>;
using Params = std::array<double, OdinHs::kParams>;

static_assert(Vessel<OdinHs>);

// Ranges stated in docs/vessels/odin-hs.md.
constexpr double kTopSpeedMin = 16.0, kTopSpeedMax = 19.0;      // [m/s], throttle 1
constexpr double kTurnRadiusMin = 20.0, kTurnRadiusMax = 60.0;  // [m], throttle 1, nozzle 27 deg

class OdinHsTest : public ::testing::Test {
 protected:
  // At rest, engines idling, bucket full ahead.
  static State AtRest() {
    State x = State::Zero();
    x(6) = OdinHs::kIdleRpm;
    x(8) = 1.0;
    return x;
  }

  // Holds `input` for `seconds` (RK4, zero-order hold).
  State Hold(State x, const Input& input, double seconds, const Params& p,
             const Environment<double>& env = {}) const {
    const auto f = [&](const double* s, double* d) {
      OdinHs::Derivative(s, input.data(), p.data(), env, d);
    };
    for (long i = 0; i < std::lround(seconds / kStep); ++i) {
      Rk4Step<double, OdinHs::kStates>(f, kStep, x);
    }
    return x;
  }
  State Hold(const State& x, const Input& input, double seconds) const {
    return Hold(x, input, seconds, params_);
  }

  State Derivative(const State& x, const Input& input) const {
    State dx;
    OdinHs::Derivative(x.data(), input.data(), params_.data(), Environment<double>{}, dx.data());
    return dx;
  }

  // Straight-line steady state at `throttle`, bucket ahead, from `start`.
  State Straight(double throttle, const State& start) const {
    return Hold(start, {throttle, 0.0, 1.0}, 300.0);
  }

  static std::string_view RegimeAt(double speed) {
    return OdinHs::Regime(OdinHs::FroudeNumber(speed));
  }

  static constexpr double kStep = 0.02;  // [s]
  Params params_ = OdinHs::kDefaultParams;
};

// The displacement-to-planing hump: the resistance coefficient R/U^2 peaks at Fn 0.4-0.7 and falls
// beyond it, dR/dU has a local minimum past Fn 0.5 (the plateau before planing), and R rises
// again when planing (friction on the remaining wetted area).
TEST_F(OdinHsTest, ResistanceHasHumpBeforePlaning) {
  const double froude_speed = std::sqrt(OdinHs::kGravity * OdinHs::kLength);
  const auto resistance = [&](double fn) {
    return OdinHs::Resistance(fn * froude_speed, params_.data());
  };
  const auto slope = [&](double fn) {
    const double d = 1e-4;
    return (resistance(fn + d) - resistance(fn - d)) / (2 * d * froude_speed);
  };
  std::vector<double> fns, coefficient, slopes;
  for (double fn = 0.1; fn <= 2.0 + 1e-9; fn += 0.01) {
    fns.push_back(fn);
    const double speed = fn * froude_speed;
    coefficient.push_back(resistance(fn) / (speed * speed));
    slopes.push_back(slope(fn));
  }
  const auto peak = std::max_element(coefficient.begin(), coefficient.end()) - coefficient.begin();
  EXPECT_GE(fns[peak], 0.4);
  EXPECT_LE(fns[peak], 0.7);
  for (std::size_t i = peak + 1; i < fns.size(); ++i) EXPECT_LT(coefficient[i], coefficient[i - 1]);
  EXPECT_LT(coefficient.back(), 0.25 * coefficient[peak]);

  bool slope_minimum_past_half = false;
  for (std::size_t i = 1; i + 1 < fns.size(); ++i) {
    if (fns[i] > 0.5 && slopes[i] < slopes[i - 1] && slopes[i] <= slopes[i + 1] &&
        slopes[i] < slope(0.5) && slopes[i] < slope(1.7)) {
      slope_minimum_past_half = true;
    }
  }
  EXPECT_TRUE(slope_minimum_past_half);
  EXPECT_GT(slope(1.7), 0.0);
  for (std::size_t i = 1; i < fns.size(); ++i) EXPECT_GT(resistance(fns[i]), 0.0);
}

// Dynamic lift takes the hull out of the water: the wetted fraction is about 1 at displacement
// speeds, falls monotonically and is about half when planing at top speed (Savitzky).
TEST_F(OdinHsTest, WettedAreaShrinksWhenPlaning) {
  const double froude_speed = std::sqrt(OdinHs::kGravity * OdinHs::kLength);
  EXPECT_GT(OdinHs::WettedFraction(0.2 * froude_speed, params_.data()), 0.99);
  const double planing = OdinHs::WettedFraction(1.7 * froude_speed, params_.data());
  EXPECT_GT(planing, 0.45);
  EXPECT_LT(planing, 0.6);
  for (double fn = 0.05; fn < 2.0; fn += 0.05) {
    EXPECT_LT(OdinHs::WettedFraction((fn + 0.05) * froude_speed, params_.data()),
              OdinHs::WettedFraction(fn * froude_speed, params_.data()));
  }
}

// Idle, half and full throttle end in the displacement, semi-displacement and planing regimes.
TEST_F(OdinHsTest, SteadySpeedRegimesFollowThrottle) {
  EXPECT_EQ(RegimeAt(Straight(0.0, AtRest())(3)), "displacement");
  EXPECT_EQ(RegimeAt(Straight(0.5, AtRest())(3)), "semi-displacement");
  EXPECT_EQ(RegimeAt(Straight(1.0, AtRest())(3)), "planing");
}

// Thrust falls and resistance (past the hump) rises slowly enough that every throttle has one
// stable straight-line speed: reached from rest and from top speed alike, rising with throttle,
// and the 0, 0.1, ..., 1 sweep visits all three regimes.
TEST_F(OdinHsTest, SteadySpeedRisesWithThrottleWithoutHysteresis) {
  const State top = Straight(1.0, AtRest());
  double previous = 0.0;
  int displacement = 0, semi = 0, planing = 0;
  for (int k = 0; k <= 10; ++k) {
    const double throttle = 0.1 * k;
    const State up = Straight(throttle, AtRest());
    const State down = Straight(throttle, top);
    EXPECT_NEAR(up(3), down(3), 1e-3) << "throttle " << throttle;
    EXPECT_LT(std::abs(Derivative(up, {throttle, 0.0, 1.0})(3)), 1e-4) << "not steady";
    EXPECT_GT(up(3), previous) << "throttle " << throttle;
    previous = up(3);
    const std::string_view regime = RegimeAt(up(3));
    displacement += regime == "displacement";
    semi += regime == "semi-displacement";
    planing += regime == "planing";
  }
  EXPECT_GE(displacement, 2);
  EXPECT_GE(semi, 2);
  EXPECT_GE(planing, 2);
}

// Top speed is where the jets' momentum thrust at 2000 rpm equals the calm-water resistance,
// 16-19 m/s (31-37 kn) for a 5 t, 10.5 m planing hull.
TEST_F(OdinHsTest, TopSpeedWithinDocumentedRange) {
  const State top = Straight(1.0, AtRest());
  const double speed = top(3);
  EXPECT_GE(speed, kTopSpeedMin);
  EXPECT_LE(speed, kTopSpeedMax);
  EXPECT_NEAR(top(6), OdinHs::kMaxRpm, 1e-6);
  const double thrust = OdinHs::SurgeThrust(top(6), speed, 1.0, 0.0, params_.data());
  EXPECT_NEAR(thrust, OdinHs::Resistance(speed, params_.data()), 1e-3 * thrust);
}

// Full nozzle at full throttle settles into a steady planing turn whose radius U / r is a few
// boat lengths (20-60 m).
TEST_F(OdinHsTest, FullNozzleTurnRadiusWithinDocumentedRange) {
  const Input turn = {1.0, OdinHs::kInputMax[1], 1.0};
  const State x = Hold(Straight(1.0, AtRest()), turn, 200.0);
  EXPECT_LT(std::abs(Derivative(x, turn)(5)), 1e-5) << "not steady";
  const double speed = std::hypot(x(3), x(4));
  const double radius = speed / x(5);
  EXPECT_GE(radius, kTurnRadiusMin);
  EXPECT_LE(radius, kTurnRadiusMax);
  EXPECT_EQ(RegimeAt(speed), "planing");
}

// Positive nozzle pushes the stern to port and turns the bow to starboard (r > 0) in every
// regime; the hull is port-starboard symmetric, so the opposite nozzle mirrors the motion.
TEST_F(OdinHsTest, PositiveNozzleGivesPositiveYawRate) {
  for (const double throttle : {0.0, 0.5, 1.0}) {
    const State start = Straight(throttle, AtRest());
    const State starboard = Hold(start, {throttle, 0.2, 1.0}, 20.0);
    const State port = Hold(start, {throttle, -0.2, 1.0}, 20.0);
    EXPECT_GT(starboard(5), 0.0) << "throttle " << throttle;
    EXPECT_GT(starboard(2), 0.0);
    EXPECT_NEAR(port(5), -starboard(5), 1e-9);
    EXPECT_NEAR(port(4), -starboard(4), 1e-9);
    EXPECT_NEAR(port(3), starboard(3), 1e-9);
  }
}

// The reversing bucket: at 0 the jets give no net thrust at rest, at -1 they drive the boat
// astern, slower than ahead (astern efficiency, no planing lift going astern).
TEST_F(OdinHsTest, BucketReversesThrust) {
  EXPECT_NEAR(OdinHs::SurgeThrust(2000.0, 0.0, 0.0, 0.0, params_.data()), 0.0, 1e-9);
  EXPECT_LT(OdinHs::SurgeThrust(2000.0, 0.0, -1.0, 0.0, params_.data()), 0.0);
  State astern = AtRest();
  astern(8) = -1.0;
  astern = Hold(astern, {1.0, 0.0, -1.0}, 300.0);
  EXPECT_LT(astern(3), -1.0);
  EXPECT_LT(-astern(3), 0.5 * Straight(1.0, AtRest())(3));
}

// Actuators are first order near the set point and slew-limited far from it: rpm rises at most
// rpm_rate_max (idle to 99 % of full in about 4 s), the nozzle turns at most 25 deg/s.
TEST_F(OdinHsTest, ActuatorsAreSlewLimited) {
  const double rpm_rate = params_[OdinHs::kRpmRate];
  const double nozzle_rate = params_[OdinHs::kNozzleRate];
  State x = AtRest();
  x(7) = OdinHs::kInputMin[1];
  const Input command = {1.0, OdinHs::kInputMax[1], -1.0};
  double t_full = -1.0;
  for (int i = 0; i < 500; ++i) {
    const State dx = Derivative(x, command);
    EXPECT_LE(dx(6), rpm_rate);
    EXPECT_LE(dx(7), nozzle_rate);
    EXPECT_GE(dx(8), -params_[OdinHs::kBucketRate]);
    if (t_full < 0 && x(6) > 0.99 * OdinHs::kMaxRpm) t_full = i * kStep;
    x = Hold(x, command, kStep);
  }
  EXPECT_GT(t_full, 3.0);
  EXPECT_LT(t_full, 4.5);
  EXPECT_NEAR(x(6), OdinHs::kMaxRpm, 0.1);
  EXPECT_NEAR(x(7), OdinHs::kInputMax[1], 1e-6);
  EXPECT_NEAR(x(8), -1.0, 1e-6);
}

// Every corner of the admissible input box (throttle 0/1, nozzle -27/0/27 deg, bucket -1/0/1)
// held for 600 s keeps the motion finite and bounded: the hull damping dissipates energy.
TEST_F(OdinHsTest, ExtremeInputsHeld600sStayFinite) {
  for (const double throttle : {0.0, 1.0}) {
    for (const double nozzle : {OdinHs::kInputMin[1], 0.0, OdinHs::kInputMax[1]}) {
      for (const double bucket : {-1.0, 0.0, 1.0}) {
        const State x = Hold(AtRest(), {throttle, nozzle, bucket}, 600.0);
        SCOPED_TRACE(::testing::Message() << throttle << " " << nozzle << " " << bucket);
        EXPECT_TRUE(x.allFinite());
        EXPECT_LT(std::hypot(x(3), x(4)), 20.0);
        EXPECT_LT(std::abs(x(5)), 1.0);
        EXPECT_NEAR(x(6), OdinHs::kIdleRpm + (OdinHs::kMaxRpm - OdinHs::kIdleRpm) * throttle, 1e-6);
      }
    }
  }
}

// A constant irrotational current carries the boat but leaves its motion through the water
// unchanged: the steady water-relative speed equals the calm steady speed.
TEST_F(OdinHsTest, CurrentLeavesWaterRelativeMotionUnchanged) {
  const Environment<double> env{0.7, -0.4};
  const double calm = Straight(0.5, AtRest())(3);
  const State x = Hold(AtRest(), {0.5, 0.0, 1.0}, 600.0, params_, env);
  const double c = std::cos(x(2)), s = std::sin(x(2));
  const double u_r = x(3) - (c * env.current_north + s * env.current_east);
  const double v_r = x(4) - (-s * env.current_north + c * env.current_east);
  EXPECT_NEAR(u_r, calm, 1e-3);
  EXPECT_NEAR(v_r, 0.0, 1e-3);
}

// Written once for every scalar: with ceres::Jet the value part equals the double result, and
// the derivatives with respect to all parameters equal central differences (relative 1e-6).
TEST_F(OdinHsTest, JetDerivativeMatchesDoubleAndCentralDifferences) {
  using J = ceres::Jet<double, OdinHs::kParams>;
  struct Case {
    State x;
    Input input;
  };
  std::vector<Case> cases(3);
  cases[0].x << 12.0, -5.0, 0.3, 9.0, -0.8, 0.12, 1500.0, 0.2, 0.03;  // over the hump
  cases[0].input = {0.7, -0.1, 0.5};
  cases[1].x << -3.0, 40.0, -2.0, 16.5, -1.4, 0.22, 2000.0, 0.45, 0.98;  // planing turn
  cases[1].input = {1.0, 0.4712, 1.0};
  cases[2].x << 0.0, 0.0, 1.0, -2.0, 0.3, -0.05, 900.0, -0.3, -0.6;  // astern
  cases[2].input = {0.2, 0.3, -1.0};
  const Environment<double> env{0.4, -0.3};
  const Environment<J> env_jet{J(0.4), J(-0.3)};
  for (const Case& c : cases) {
    std::array<J, OdinHs::kStates> x_jet, dx_jet;
    std::array<J, OdinHs::kInputs> in_jet;
    std::array<J, OdinHs::kParams> p_jet;
    for (int i = 0; i < OdinHs::kStates; ++i) x_jet[i] = J(c.x(i));
    for (int i = 0; i < OdinHs::kInputs; ++i) in_jet[i] = J(c.input[i]);
    for (int j = 0; j < OdinHs::kParams; ++j) p_jet[j] = J(params_[j], j);
    OdinHs::Derivative(x_jet.data(), in_jet.data(), p_jet.data(), env_jet, dx_jet.data());
    State dx;
    OdinHs::Derivative(c.x.data(), c.input.data(), params_.data(), env, dx.data());
    // Jet divides by multiplying with the inverse: equal up to rounding.
    for (int i = 0; i < OdinHs::kStates; ++i) {
      EXPECT_NEAR(dx_jet[i].a, dx(i), 1e-12 * std::max(std::abs(dx(i)), 1.0));
    }

    for (int j = 0; j < OdinHs::kParams; ++j) {
      const double h = 1e-6 * std::max(std::abs(params_[j]), 1.0);
      Params plus = params_, minus = params_;
      plus[j] += h;
      minus[j] -= h;
      State dx_plus, dx_minus;
      OdinHs::Derivative(c.x.data(), c.input.data(), plus.data(), env, dx_plus.data());
      OdinHs::Derivative(c.x.data(), c.input.data(), minus.data(), env, dx_minus.data());
      for (int i = 0; i < OdinHs::kStates; ++i) {
        const double central = (dx_plus(i) - dx_minus(i)) / (2 * h);
        // Rounding floor of the difference quotient: 1e-13 of the rate per step.
        const double floor = 1e-13 * std::abs(dx(i)) / h;
        EXPECT_NEAR(dx_jet[i].v[j], central, 1e-6 * std::abs(central) + floor)
            << OdinHs::kStateNames[i] << " / " << OdinHs::kParamNames[j];
      }
    }
  }
}

}  // namespace
}  // namespace usvid
