// Closed-loop replay (metrics/closed_loop_replay.h): a test zig-zag re-run on the model by the
// maneuver's own rule, and its criteria against the record's.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "maneuvers/maneuver_factory.h"
#include "metrics/closed_loop_replay.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A noise-free record of `spec` on the vessel's nominal model.
Dataset Record(const std::string& vessel, const std::string& spec, double seconds) {
  const VesselSimulator& sim = FindVessel(vessel);
  auto m = MakeManeuver(spec, sim.Info().actuation, seconds, 1);
  return sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
}

// The true model replays the record: the same reversals, so the same overshoots (the record's
// first state is its steady approach, from which the simulator's run-in starts too).
TEST(ManeuverReplayTest, TheTrueModelHasTheRecordsCriteria) {
  for (const std::string vessel : {"odin3dof", "odin-hs"}) {
    const Dataset record = Record(vessel, "zigzag:20/20", 120.0);
    const nlohmann::json score =
        ClosedLoopScore({{"vessel", vessel}}, vessel, "zigzag:20/20", record);
    ASSERT_EQ(score.at("status"), "ok") << vessel << ": " << score.dump();
    EXPECT_NEAR(score.at("first_overshoot_error_deg").get<double>(), 0.0, 0.05) << vessel;
    EXPECT_NEAR(score.at("second_overshoot_error_deg").get<double>(), 0.0, 0.05) << vessel;
    EXPECT_NEAR(score.at("second_execute_error_s").get<double>(), 0.0, 0.06) << vessel;
    EXPECT_GT(score.at("measured").at("first_overshoot_deg").get<double>(), 1.0) << vessel;
  }
}

// A test steered about a base course off its heading at the execute (MARIN's KVLCC2 zig-zags:
// 1.12 deg) is replayed about the same course, and its overshoots read about it. Replayed about
// the model's own heading at the execute, the true model's first leg would turn 1.12 deg less
// and its overshoots would be read 1.12 deg off on each side. (On KVLCC2, which turns 0.05 deg
// between samples; odin3dof turns 4.6 deg, too coarse to read a base course of a degree or two
// from: metrics/zigzag_response.h.)
TEST(ManeuverReplayTest, TheReplayReversesAboutTheRecordsBaseCourse) {
  for (const double offset_deg : {1.12, -2.0}) {
    const VesselSimulator& sim = FindVessel("kvlcc2");
    ManeuverSpec spec = ParseManeuverSpec("zigzag:20/20");
    spec.base_offset_rad = offset_deg * kDeg;
    auto m = MakeManeuver(spec, sim.Info().actuation, 450.0, 1);
    const Dataset record = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
    const nlohmann::json score =
        ClosedLoopScore({{"vessel", "kvlcc2"}}, "kvlcc2", "zigzag:20/20", record);
    ASSERT_EQ(score.at("status"), "ok") << score.dump();
    EXPECT_NEAR(score.at("first_overshoot_error_deg").get<double>(), 0.0, 0.1) << offset_deg;
    EXPECT_NEAR(score.at("second_overshoot_error_deg").get<double>(), 0.0, 0.1) << offset_deg;
    EXPECT_NEAR(score.at("second_execute_error_s").get<double>(), 0.0, 0.06) << offset_deg;
  }
}

// The point of a closed loop: the model's yaw command reverses when the model's own heading has
// turned 20 deg, not when the recorded hull's did. A model that turns more slowly than the
// hull reverses later than the record.
TEST(ManeuverReplayTest, TheModelReversesOnItsOwnHeading) {
  const Dataset record = Record("odin3dof", "zigzag:20/20", 60.0);
  const nlohmann::json model = {
      {"equations", {{"u", "0 * u"}, {"v", "-v"}, {"r", "0.000005 * tau_n - r"}}},
      {"inputs", {"tau_x", "tau_y", "tau_n"}}};
  const ClosedLoopReplay replay = ReplayManeuver(model, "odin3dof", "zigzag:20/20", record);
  ASSERT_FALSE(replay.diverged);
  const Dataset& run = replay.run;
  const Eigen::VectorXd& yaw = run["tau_n"];
  const Eigen::VectorXd& psi = run["psi"];
  Eigen::Index execute = -1, reversal = -1;
  for (Eigen::Index k = 1; k < run.rows() && reversal < 0; ++k) {
    if (execute < 0 && yaw(k) != yaw(0)) execute = k;
    if (execute >= 0 && k > execute && yaw(k) * yaw(execute) < 0) reversal = k;
  }
  ASSERT_GT(reversal, 0);
  const double step_deg = std::abs(run["r"](reversal)) / 20.0 / kDeg;  // a sample's turn
  EXPECT_NEAR((psi(reversal) - psi(execute)) / kDeg, 20.0, step_deg + 0.3);
  const nlohmann::json score = ClosedLoopScore(model, "odin3dof", "zigzag:20/20", record);
  EXPECT_GT(score.at("second_execute_error_s").get<double>(), 0.5) << score.dump();
}

// A measured track's model reads a disturbance the record logs (the wind, the current): the
// replay feeds it as recorded, in time. A yaw disturbance logged from 30 s on turns the replayed
// hull from then on, and not before.
TEST(ManeuverReplayTest, ALoggedDisturbanceFollowsTheRecordInTime) {
  Dataset calm = Record("odin3dof", "zigzag:20/20", 60.0);
  Dataset pushed = calm;
  const Eigen::VectorXd t = calm.t();
  calm.Set("current_v", Eigen::VectorXd::Zero(t.size()));
  pushed.Set("current_v", (t.array() >= 30.0).cast<double>().matrix() * 0.02);
  const nlohmann::json model = {
      {"equations", {{"u", "0 * u"}, {"v", "-v"}, {"r", "0.000005 * tau_n - r + current_v"}}},
      {"inputs", {"tau_x", "tau_y", "tau_n", "current_v"}}};
  const ClosedLoopReplay a = ReplayManeuver(model, "odin3dof", "zigzag:20/20", calm);
  const ClosedLoopReplay b = ReplayManeuver(model, "odin3dof", "zigzag:20/20", pushed);
  ASSERT_FALSE(a.diverged);
  ASSERT_FALSE(b.diverged);
  const Eigen::Index n = std::min(a.run.rows(), b.run.rows());
  double before = 0.0, after = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const double d = std::abs(b.run["r"](k) - a.run["r"](k));
    (a.run.t()(k) < 29.9 ? before : after) = std::max(a.run.t()(k) < 29.9 ? before : after, d);
  }
  EXPECT_EQ(before, 0.0);
  EXPECT_GT(after, 0.005);
}

// Waterjet models read the jets' states: the replay drives them through actuator dynamics
// identified on the record (its nozzle moves; its throttle is held, so the rpm is held too).
TEST(ManeuverReplayTest, AJetStateModelRunsThroughIdentifiedActuators) {
  const Dataset record = Record("odin-hs", "zigzag:20/20", 90.0);
  const nlohmann::json model = {
      {"equations", {{"u", "0 * u"}, {"v", "-v"}, {"r", "0.8 * nozzle_angle - r"}}},
      {"inputs", {"nozzle_angle"}}};
  const nlohmann::json score = ClosedLoopScore(model, "odin-hs", "zigzag:20/20", record);
  ASSERT_EQ(score.at("status"), "ok") << score.dump();
  EXPECT_TRUE(score.at("model").at("first_overshoot_deg").is_number()) << score.dump();
}

// Rows that cannot be replayed say why instead of leaving the field out.
TEST(ManeuverReplayTest, WhatCannotBeReplayedSaysSo) {
  const Dataset record = Record("odin3dof", "zigzag:20/20", 40.0);
  const nlohmann::json truth = {{"vessel", "odin3dof"}};
  EXPECT_TRUE(ClosedLoopScore(truth, "odin3dof", "random-steps", record)
                  .at("status")
                  .get<std::string>()
                  .starts_with("not replayable: random-steps is open-loop"));
  EXPECT_TRUE(ClosedLoopScore(truth, "odin3dof", "", record)
                  .at("status")
                  .get<std::string>()
                  .starts_with("not replayable: recorded inputs only"));
  // An input that is no command and that the test record does not log.
  const nlohmann::json foreign = {{"equations", {{"u", "-u"}, {"v", "-v"}, {"r", "wind - r"}}}};
  const nlohmann::json score = ClosedLoopScore(foreign, "odin3dof", "zigzag:20/20", record);
  EXPECT_NE(score.at("status").get<std::string>().find("input 'wind' is neither a command"),
            std::string::npos)
      << score.dump();
  EXPECT_FALSE(score.contains("first_overshoot_error_deg"));
}

}  // namespace
}  // namespace usvid
