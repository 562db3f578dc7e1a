// The yaw constant set by the training zig-zags' overshoots (metrics/yaw_bias_calibration.h). A
// record made by a model whose yaw carries a constant moment, replayed closed-loop on kvlcc2's
// rudder, overshoots further to one side than to the other; the same model without the constant
// does not, and the calibration gives it back.
#include "metrics/yaw_bias_calibration.h"

#include <gtest/gtest.h>

#include "core/records.h"
#include "maneuvers/maneuver_factory.h"
#include "metrics/closed_loop_replay.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

// A first-order yaw (time constant 33 s) whose rudder moment grows with the speed, at constant
// speed; `constant` is the moment that makes it asymmetric.
nlohmann::json Model(const std::string& constant) {
  return {
      {"vessel", "kvlcc2"},
      {"inputs", {"delta", "rev"}},
      {"equations",
       {{"u", "0 * u"}, {"v", "-0.05 * v"}, {"r", constant + " - 1e-4 * u * delta - 0.03 * r"}}}};
}

// The zig-zag `spec` run by `model`, as a record at 5 Hz: the simulator's approach (kvlcc2 at
// its cruise), then the model's own replay.
Dataset ZigzagOf(const nlohmann::json& model, const std::string& spec) {
  const VesselSimulator& sim = FindVessel("kvlcc2");
  auto m = MakeManeuver(spec, sim.Info().actuation, 300.0, 1);
  RunOptions at_5hz;  // a tanker's zig-zag needs no more, and the test runs some 60 replays
  at_5hz.rate_hz = 5.0;
  at_5hz.dt = 0.1;
  const Dataset approach = sim.RunManeuver(*m, sim.Info().default_params, {}, at_5hz).data;
  const ClosedLoopReplay replay = ReplayManeuver(model, "kvlcc2", spec, approach);
  EXPECT_FALSE(replay.diverged);

  return replay.run;
}

TEST(YawBiasCalibrationTest, FindsTheConstantThatMakesTheZigzagAsymmetric) {
  const Dataset record = ZigzagOf(Model("2e-5"), "zigzag:-20/20");
  nlohmann::json model = Model("0");
  const nlohmann::json before = ClosedLoopScore(model, "kvlcc2", "zigzag:-20/20", record);
  ASSERT_EQ(before["status"], "ok") << before.dump();
  // The premise: without the constant, the overshoots are off, to either side.
  EXPECT_GT(std::abs(before["first_overshoot_error_deg"].get<double>()), 0.5) << before.dump();

  const nlohmann::json report = CalibrateYawBias(model, record, "");
  ASSERT_TRUE(report["applied"].get<bool>()) << report.dump();
  EXPECT_EQ(report["maneuvers"], nlohmann::json::array({"zigzag:-20/20"}));
  EXPECT_NEAR(report["constant_after"].get<double>(), 2e-5, 0.1e-5) << report.dump();
  const nlohmann::json after = ClosedLoopScore(model, "kvlcc2", "zigzag:-20/20", record);
  EXPECT_LT(std::abs(after["first_overshoot_error_deg"].get<double>()), 0.1) << after.dump();
  EXPECT_LT(std::abs(after["second_overshoot_error_deg"].get<double>()), 0.1) << after.dump();
  // The rest of the equation is as it was.
  EXPECT_NE(model["equations"]["r"].get<std::string>().find(" - 1e-4 * u * delta - 0.03 * r"),
            std::string::npos)
      << model["equations"]["r"];
}

TEST(YawBiasCalibrationTest, ReadsEachZigzagOfSeveralRecordsAndSkipsTheOthers) {
  const nlohmann::json truth = Model("-1.5e-5");
  Dataset turn = ZigzagOf(truth, "zigzag:20/20");  // a record without a zig-zag: its rudder held
  turn.Set("delta", Eigen::VectorXd::Constant(turn.rows(), 0.35));
  const Dataset joined =
      JoinRecords({ZigzagOf(truth, "zigzag:-20/20"), turn, ZigzagOf(truth, "zigzag:20/20")});
  nlohmann::json model = Model("0");
  const nlohmann::json report = CalibrateYawBias(model, joined, "kvlcc2");
  ASSERT_TRUE(report["applied"].get<bool>()) << report.dump();
  EXPECT_EQ(report["maneuvers"], nlohmann::json::array({"zigzag:-20/20", "zigzag:20/20"}));
  EXPECT_NEAR(report["constant_after"].get<double>(), -1.5e-5, 0.1e-5) << report.dump();
  EXPECT_EQ(report["overshoot_errors_after"].size(), 4u);
}

TEST(YawBiasCalibrationTest, WithoutAZigzagOrAVesselTheModelStaysAsItIsAndSaysWhy) {
  const Dataset record = ZigzagOf(Model("2e-5"), "zigzag:-20/20");
  Dataset held = record;
  held.Set("delta", Eigen::VectorXd::Constant(held.rows(), 0.35));
  nlohmann::json model = Model("0");
  const nlohmann::json unchanged = model;
  EXPECT_EQ(CalibrateYawBias(model, held, "kvlcc2")["reason"],
            "no zig-zag among the training records");
  nlohmann::json vesselless = model;
  vesselless.erase("vessel");
  EXPECT_EQ(CalibrateYawBias(vesselless, record, "")["reason"],
            "no vessel to take the replay's rudder from");
  EXPECT_EQ(model, unchanged);

  // Only a model that asks is calibrated, and its request becomes the report.
  CalibrateRequested(model, record, "");
  EXPECT_EQ(model, unchanged);
  model["calibration"] = {{"yaw_bias", "zigzag"}};
  CalibrateRequested(model, record, "");
  EXPECT_TRUE(model["calibration"]["yaw_bias"]["applied"].get<bool>());
  EXPECT_NE(model["equations"], unchanged["equations"]);
}

}  // namespace
}  // namespace usvid
