// The maneuvers (docs/data.md#maneuvers), run on the simulators: the zig-zag switches exactly when
// the heading passes the threshold and reports its overshoots, turns to port first for a
// negative A, and ramps its yaw command within the actuation's rate limit; the turning circle
// reports its geometry; the step grid reaches steady state on every step; the random maneuvers
// vary the throttle and stay within the inputs' ranges; all are reproducible from the seed.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "core/error.h"
#include "maneuvers/maneuver_factory.h"
#include "maneuvers/zigzag.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

class ManeuversTest : public ::testing::Test {
 protected:
  static SimulationResult Run(const std::string& vessel, const std::string& spec, uint64_t seed = 1,
                              double duration = 0.0) {
    const VesselSimulator& sim = FindVessel(vessel);
    auto m = MakeManeuver(spec, sim.Info().actuation, duration, seed);
    SimulationResult r = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{});
    EXPECT_FALSE(r.diverged);
    return r;
  }
};

// Kempf zig-zag: the yaw command changes sign at exactly the ticks where the heading first
// passes +-B from the initial heading, and the overshoots in the report are the excursions
// beyond B measured in the data.
TEST_F(ManeuversTest, ZigZagSwitchesWhenHeadingPassesThreshold) {
  for (const std::string vessel : {"odin3dof", "eb2dof"}) {
    const SimulationResult r = Run(vessel, "zigzag:20/10", 1, 200);
    const Dataset& d = r.data;
    const std::string heading = vessel == "eb2dof" ? "chi" : "psi";
    const std::string yaw = vessel == "eb2dof" ? "nozzle" : "tau_n";
    const Eigen::VectorXd& psi = d[heading];
    const Eigen::VectorXd& cmd = d[yaw];
    const double threshold = 10 * kDeg;
    int sign = 0, switches = 0;
    std::vector<double> beyond;
    for (Eigen::Index k = 0; k < d.rows(); ++k) {
      if (cmd(k) == 0.0) continue;  // the straight approach
      const int s = cmd(k) > 0 ? 1 : -1;
      if (sign != 0 && s != sign) {
        ++switches;
        // At the switch the heading has reached the threshold on the side it was turning to...
        EXPECT_GE(sign * psi(k), threshold - 1e-12) << vessel << " t=" << d.t()(k);
        // ...and one tick earlier it had not.
        EXPECT_LT(sign * psi(k - 1), threshold) << vessel << " t=" << d.t()(k);
        beyond.push_back(0.0);
      }
      if (!beyond.empty()) beyond.back() = std::max(beyond.back(), s * -psi(k) - threshold);
      sign = s;
    }
    EXPECT_GE(switches, 4) << vessel;
    const auto& report = r.maneuver.at("report");
    EXPECT_NEAR(report.at("first_overshoot_deg").get<double>(), beyond[0] / kDeg, 1e-9);
    EXPECT_NEAR(report.at("second_overshoot_deg").get<double>(), beyond[1] / kDeg, 1e-9);
    EXPECT_GT(report.at("first_overshoot_deg").get<double>(), 0.0);
  }
}

// Actuation::SlewYaw: the command moves towards the target by at most yaw_rate_limit * dt, lands
// on the target when it is nearer than that, never moves for a negative dt, and steps straight
// to the target when yaw_rate_limit is 0.
TEST_F(ManeuversTest, SlewYawMovesAtMostRateTimesDt) {
  Actuation act = FindVessel("odin3dof").Info().actuation;
  act.yaw_rate_limit = 4000.0;  // N m / s
  EXPECT_DOUBLE_EQ(act.SlewYaw(1000.0, 11000.0, 0.05), 1200.0);
  EXPECT_DOUBLE_EQ(act.SlewYaw(1000.0, -11000.0, 0.05), 800.0);
  EXPECT_DOUBLE_EQ(act.SlewYaw(1000.0, 1150.0, 0.05), 1150.0);  // within reach: no overshoot
  EXPECT_DOUBLE_EQ(act.SlewYaw(1000.0, 11000.0, 1.0), 5000.0);
  EXPECT_DOUBLE_EQ(act.SlewYaw(1000.0, 11000.0, -1.0), 1000.0);
  act.yaw_rate_limit = 0.0;
  EXPECT_DOUBLE_EQ(act.SlewYaw(1000.0, 11000.0, 0.05), 11000.0);
  EXPECT_DOUBLE_EQ(act.SlewYaw(1000.0, -11000.0, 0.0), -11000.0);
}

// zigzag:-A/B turns to port first: on a vessel whose positive yaw input turns to starboard
// (odin3dof, yaw_sign +1) the first yaw command off neutral is negative, the heading first
// passes -B, and the spec keeps the sign.
TEST_F(ManeuversTest, ZigZagNegativeRudderTurnsToPortFirst) {
  const Actuation& act = FindVessel("odin3dof").Info().actuation;
  ASSERT_EQ(act.yaw_sign, 1.0);
  EXPECT_EQ(ZigZag(act, -20, 20, 200).Spec(), "zigzag:-20/20");
  EXPECT_EQ(MakeManeuver("zigzag:-20/20", act, 200, 1)->Spec(), "zigzag:-20/20");
  EXPECT_EQ(MakeManeuver("zigzag:20/20", act, 200, 1)->Spec(), "zigzag:20/20");

  const SimulationResult r = Run("odin3dof", "zigzag:-20/20", 1, 200);
  const Dataset& d = r.data;
  const Eigen::VectorXd& cmd = d["tau_n"];
  const Eigen::VectorXd& psi = d["psi"];
  const double neutral = act.neutral[act.yaw_input];
  Eigen::Index first = -1;
  for (Eigen::Index k = 0; k < d.rows() && first < 0; ++k)
    if (cmd(k) != neutral) first = k;
  ASSERT_GE(first, 0) << "the yaw command never left neutral";
  EXPECT_LT(cmd(first), 0.0);
  EXPECT_DOUBLE_EQ(cmd(first), act.YawCommand(-20));
  // The first switch (command back to starboard) comes when the heading has reached -B.
  Eigen::Index first_switch = -1;
  for (Eigen::Index k = first; k < d.rows() && first_switch < 0; ++k)
    if (cmd(k) > 0) first_switch = k;
  ASSERT_GE(first_switch, 0) << "no switch in 200 s";
  EXPECT_LE(psi(first_switch), -20 * kDeg);
  EXPECT_GT(psi(first_switch - 1), -20 * kDeg);
  const auto& report = r.maneuver.at("report");
  ASSERT_GE(report.at("switch_times_s").size(), 2u);
  EXPECT_NEAR(report.at("switch_times_s")[0].get<double>(), d.t()(first_switch), 1e-9);
  EXPECT_GT(report.at("first_overshoot_deg").get<double>(), 0.0);
}

// A zig-zag on an odin3dof given a yaw rate limit: the recorded yaw command changes by at most
// yaw_rate_limit x the control period between ticks once the rudder has been put over, and still
// reaches the full +-A command on each leg.
class ZigZagSlewTest : public ManeuversTest {
 protected:
  static constexpr double kRate = 4000.0;  // N m / s: 20/35 of 20 kN m takes about 2.9 s
  static SimulationResult RunSlewed() {
    const VesselSimulator& sim = FindVessel("odin3dof");
    Actuation act = sim.Info().actuation;
    act.yaw_rate_limit = kRate;
    ZigZag m(act, 20, 10, 200);
    SimulationResult r = sim.RunManeuver(m, sim.Info().default_params, {}, RunOptions{});
    EXPECT_FALSE(r.diverged);
    return r;
  }
  static double Period() { return 1.0 / RunOptions{}.rate_hz; }
};

TEST_F(ZigZagSlewTest, YawCommandRampsWithinRateLimit) {
  const SimulationResult r = RunSlewed();
  const Actuation& act = FindVessel("odin3dof").Info().actuation;
  const Eigen::VectorXd& cmd = r.data["tau_n"];
  const double neutral = act.neutral[act.yaw_input];
  Eigen::Index first = -1;
  for (Eigen::Index k = 0; k < r.data.rows() && first < 0; ++k)
    if (cmd(k) != neutral) first = k;
  ASSERT_GE(first, 0);
  const double max_step = kRate * Period();
  double largest = 0.0;
  int steps_at_limit = 0;
  for (Eigen::Index k = first + 1; k < r.data.rows(); ++k) {
    const double step = std::abs(cmd(k) - cmd(k - 1));
    largest = std::max(largest, step);
    if (step > 0.99 * max_step) ++steps_at_limit;
    EXPECT_LE(step, max_step * (1 + 1e-9)) << "t=" << r.data.t()(k);
  }
  // The limit is what shapes the command: it ramps at the limit through each reversal...
  EXPECT_GE(steps_at_limit, 4 * 50);
  // ...and still reaches the full command both ways.
  EXPECT_NEAR(cmd.maxCoeff(), act.YawCommand(20), 1e-6);
  EXPECT_NEAR(cmd.minCoeff(), act.YawCommand(-20), 1e-6);
  EXPECT_GE(r.maneuver.at("report").at("switch_times_s").size(), 4u);
}

// The rudder execution itself (the first tick off neutral, after the lead-in) is rate limited
// too: the lead-in counts as time the rudder rested, not as time it could have moved.
TEST_F(ZigZagSlewTest, ExecutionStepIsRateLimited) {
  const SimulationResult r = RunSlewed();
  const Actuation& act = FindVessel("odin3dof").Info().actuation;
  const Eigen::VectorXd& cmd = r.data["tau_n"];
  const double neutral = act.neutral[act.yaw_input];
  for (Eigen::Index k = 1; k < r.data.rows(); ++k) {
    if (cmd(k - 1) != neutral) break;
    EXPECT_LE(std::abs(cmd(k) - cmd(k - 1)), kRate * Period() * (1 + 1e-9))
        << "t=" << r.data.t()(k);
  }
}

// Turning circle: the steady radius equals U / r at the end; the tactical diameter is about
// twice the steady radius for a hull that reaches steady turning quickly.
TEST_F(ManeuversTest, TurningReportsItsGeometry) {
  const SimulationResult r = Run("eb2dof", "turning:20", 1, 200);
  const auto& rep = r.maneuver.at("report");
  const Dataset& d = r.data;
  const Eigen::Index last = d.rows() - 1;
  EXPECT_NEAR(rep.at("steady_turning_radius_m").get<double>(), d["U"](last) / d["r"](last), 1e-6);
  EXPECT_GT(rep.at("tactical_diameter_m").get<double>(), 0.0);
  EXPECT_GT(rep.at("advance_m").get<double>(), 0.0);
}

// Step grid: every step of the grid is held to a detected steady state, where the speed and
// rate derivatives are small, and the thrust levels cover the thrust range.
TEST_F(ManeuversTest, StepGridReachesSteadyStateOnEveryStep) {
  const SimulationResult r = Run("eb2dof", "stepgrid:3/2");
  const auto& steps = r.maneuver.at("report").at("steps");
  ASSERT_EQ(steps.size(), 3u * 5u);
  std::set<double> thrusts;
  for (const auto& s : steps) {
    ASSERT_TRUE(s.contains("steady_from_s")) << s.dump();
    thrusts.insert(s.at("thrust").get<double>());
    // The data at the steady time show the steady speed.
    const double t = s.at("steady_from_s").get<double>();
    const Eigen::Index k = static_cast<Eigen::Index>(std::llround(t * 20.0));
    EXPECT_NEAR(r.data["U"](k), s.at("steady_speed").get<double>(), 1e-9);
  }
  EXPECT_EQ(thrusts.size(), 3u);
  EXPECT_NEAR(*thrusts.rbegin(), 1.0, 1e-12);
}

// Random steps, PRBS and multisine vary the throttle (not held: the report's lesson), keep
// every input within its range, and give the same run for the same seed.
TEST_F(ManeuversTest, RandomManeuversVaryThrottleWithinRange) {
  const VesselInfo& info = FindVessel("eb2dof").Info();
  for (const std::string spec : {"random-steps", "prbs", "multisine"}) {
    const SimulationResult a = Run("eb2dof", spec, 3, 300), b = Run("eb2dof", spec, 3, 300);
    const SimulationResult c = Run("eb2dof", spec, 4, 300);
    for (size_t i = 0; i < info.inputs.size(); ++i) {
      const Eigen::VectorXd& u = a.data[info.inputs[i]];
      EXPECT_GE(u.minCoeff(), info.actuation.input_min[i] - 1e-12) << spec;
      EXPECT_LE(u.maxCoeff(), info.actuation.input_max[i] + 1e-12) << spec;
      EXPECT_GT(u.maxCoeff() - u.minCoeff(),
                0.2 * (info.actuation.input_max[i] - info.actuation.input_min[i]))
          << spec << " " << info.inputs[i];
    }
    EXPECT_EQ(a.data["U"], b.data["U"]) << spec;
    EXPECT_NE(a.data["U"], c.data["U"]) << spec;
  }
  // PRBS is binary per input.
  const SimulationResult p = Run("eb2dof", "prbs", 3, 300);
  std::set<double> levels(p.data["nozzle"].data(), p.data["nozzle"].data() + p.data.rows());
  EXPECT_EQ(levels.size(), 2u);
}

// Maneuvers that need a heading or a thrust input refuse vessels without them; bad specs name
// themselves.
TEST_F(ManeuversTest, BadSpecsAreRefused) {
  const Actuation& msd = FindVessel("msd").Info().actuation;
  const Actuation& odin = FindVessel("odin3dof").Info().actuation;
  EXPECT_THROW(MakeManeuver("zigzag:20/20", msd, 0, 1), InputError);
  EXPECT_THROW(MakeManeuver("stepgrid", msd, 0, 1), InputError);
  EXPECT_THROW(MakeManeuver("zigzag:20", odin, 0, 1), InputError);
  EXPECT_THROW(MakeManeuver("zigzag:a/b", odin, 0, 1), InputError);
  EXPECT_THROW(MakeManeuver("spiral", odin, 0, 1), InputError);
  EXPECT_THROW(MakeManeuver("prbs:-1", odin, 0, 1), InputError);
  EXPECT_THROW(MakeManeuver("prbs", odin, -5, 1), InputError);
  EXPECT_NO_THROW(MakeManeuver("random-steps", msd, 0, 1));
}

}  // namespace
}  // namespace usvid
