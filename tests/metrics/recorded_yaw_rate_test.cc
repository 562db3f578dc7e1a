// How fast a record's yaw command moves, and how the closed-loop replay of an equation model moves
// it (metrics/recorded_yaw_rate.h): as the record's did, so that a model fitted to a log of
// rudder orders is not given the steering gear's lag a second time.
#include "metrics/recorded_yaw_rate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "effects/effect.h"
#include "maneuvers/maneuver_factory.h"
#include "metrics/closed_loop_replay.h"
#include "simulation/simulate_record.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A 10 Hz record of one channel from a function of time.
template <typename F>
Dataset Channel(double seconds, F f) {
  const auto n = static_cast<Eigen::Index>(seconds * 10.0) + 1;
  Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(n, 0.0, 0.1 * static_cast<double>(n - 1));
  Dataset d(t);
  Eigen::VectorXd x(n);
  for (Eigen::Index k = 0; k < n; ++k) x(k) = f(t(k));
  d.Set("delta", x);
  return d;
}

// A log of orders jumps between two samples: its moves' rate is the jump over one sample period.
TEST(RecordedYawRateTest, AnOrderJumpsWithinOneSample) {
  const Dataset d = Channel(60.0, [](double t) { return t < 10 ? 0.0 : t < 30 ? 20.0 : -20.0; });
  EXPECT_NEAR(LargeMoveRate(d, "delta", 2.0), 40.0 / 0.1, 1e-6);
}

// A logged rudder angle ramps at its gear's rate, held between moves: the rate is the ramp's,
// also when the log reads the angle in steps of 0.59 deg (Esso Osaka's resolution) so that it
// holds for a sample inside the ramp.
TEST(RecordedYawRateTest, ALoggedAngleMovesAtItsRamp) {
  auto ramp = [](double t) {
    const double up = std::clamp(13.0 * (t - 10.0), 0.0, 20.0);
    return up - std::clamp(13.0 * (t - 30.0), 0.0, 40.0);
  };
  EXPECT_NEAR(LargeMoveRate(Channel(60.0, ramp), "delta", 2.0), 13.0, 0.5);
  auto quantised = [&](double t) { return 0.59 * std::round(ramp(t) / 0.59); };
  EXPECT_NEAR(LargeMoveRate(Channel(60.0, quantised), "delta", 2.0), 13.0, 1.5);
}

// Small moves (an operator's trim, a sensor's noise) are no moves of a test; a record without a
// large move, or without the channel, has no rate.
TEST(RecordedYawRateTest, SmallMovesAndMissingChannelsHaveNoRate) {
  const Dataset d = Channel(60.0, [](double t) { return 0.5 * std::sin(t); });
  EXPECT_EQ(LargeMoveRate(d, "delta", 2.0), 0.0);
  EXPECT_EQ(LargeMoveRate(d, "rudder", 2.0), 0.0);
}

// kvlcc2's zig-zag, simulated: its rudder moves at the vessel's 2.32 deg/s. The same test as a log
// of orders: each move jumps to where the simulated one ended.
Dataset SimulatedZigzag() {
  const VesselSimulator& sim = FindVessel("kvlcc2");
  auto m = MakeManeuver("zigzag:20/20", sim.Info().actuation, 400.0, 1);
  return sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
}
Dataset AsOrders(Dataset record) {
  Eigen::VectorXd delta = record["delta"];
  const double full = delta.cwiseAbs().maxCoeff();
  double sign = 0.0;
  for (Eigen::Index k = 1; k < delta.size(); ++k) {
    const double d = record["delta"](k) - record["delta"](k - 1);
    if (d != 0.0) sign = d > 0 ? 1.0 : -1.0;
    delta(k) = sign * full;
  }
  record.Set("delta", delta);
  return record;
}

// The replay's limit: the vessel's on a record that moves at it, a step on a log of orders.
TEST(RecordedYawRateTest, TheReplayStepsWhereTheRecordSteps) {
  const Actuation& act = FindVessel("kvlcc2").Info().actuation;
  const Dataset slewed = SimulatedZigzag();
  EXPECT_NEAR(LargeMoveRate(slewed, "delta", 2.0 * kDeg), act.yaw_rate_limit,
              0.02 * act.yaw_rate_limit);
  EXPECT_EQ(ReplayYawRateLimit(act, slewed), act.yaw_rate_limit);
  EXPECT_EQ(ReplayYawRateLimit(act, AsOrders(slewed)), 0.0);
}

// A suite's simulated tests log the yaw command as the maneuver slewed it, at the vessel's rate,
// under the realistic suite's sea, sensors, gaps and hidden effects too: their replays keep the
// vessel's rate, so no simulated suite's row changes with the record's reading. (odin3dof's yaw
// moment steps in the simulator too: its limit is 0 either way.)
TEST(RecordedYawRateTest, SimulatedTestsMoveAtTheVesselsRate) {
  for (const std::string vessel : {"odin3dof", "odin-hs", "kvlcc2"}) {
    for (const std::string maneuver : {"zigzag:20/20", "turning:35"}) {
      RecordRecipe recipe;
      recipe.vessel = vessel;
      recipe.maneuver = maneuver;
      recipe.duration_s = vessel == "kvlcc2" ? 400.0 : 120.0;
      recipe.effects = ParseEffects({"current=0.3", "sensor_bias=0.0017", "saturation=0.8"}, 3);
      recipe.gusts = vessel == "kvlcc2" ? "" : "8";  // kvlcc2 has no wind model
      recipe.sensors = {"0.3", 0.02, {"imu=50", "gps=5"}, {"gps=0.05"}};
      recipe.seed = 3;
      const Dataset record = SimulateRecord(recipe).data;
      const Actuation& act = FindVessel(vessel).Info().actuation;
      EXPECT_EQ(ReplayYawRateLimit(act, record), act.yaw_rate_limit) << vessel << " " << maneuver;
    }
  }
}

// The seconds the replay's rudder takes from its execute to 19 deg.
double SecondsToPutOver(const ClosedLoopReplay& replay) {
  const Eigen::VectorXd& delta = replay.run["delta"];
  const Eigen::VectorXd& t = replay.run.t();
  double execute = NAN;
  for (Eigen::Index k = 1; k < delta.size(); ++k) {
    if (std::isnan(execute) && delta(k) != delta(0)) execute = t(k - 1);
    if (std::abs(delta(k)) >= 19.0 * kDeg) return t(k) - execute;
  }
  return NAN;
}

// An equation model's replay puts the rudder over as the record did: in one sample on a log of
// orders, at the gear's rate on a log of angles. A vessel model simulates its own gear: at the
// vessel's rate on either.
TEST(RecordedYawRateTest, AnEquationModelsRudderMovesAsTheRecordsDid) {
  const Dataset slewed = SimulatedZigzag();
  const Dataset orders = AsOrders(slewed);
  const nlohmann::json equations = {
      {"equations", {{"u", "0 * u"}, {"v", "-0.01 * v"}, {"r", "-0.01 * r - 0.0001 * delta"}}},
      {"inputs", {"delta", "rev"}}};
  const double gear_s = 20.0 / 2.32;
  EXPECT_NEAR(SecondsToPutOver(ReplayManeuver(equations, "kvlcc2", "zigzag:20/20", slewed)),
              19.0 / 2.32, 1.0);
  EXPECT_LE(SecondsToPutOver(ReplayManeuver(equations, "kvlcc2", "zigzag:20/20", orders)), 1.0);
  const nlohmann::json vessel = {{"vessel", "kvlcc2"}};
  EXPECT_GT(SecondsToPutOver(ReplayManeuver(vessel, "kvlcc2", "zigzag:20/20", orders)),
            0.8 * gear_s);
}

}  // namespace
}  // namespace usvid
