// A grey-box model chosen among its alternatives by the training records' closed-loop tests
// (metrics/closed_loop_choice.h). The record is kvlcc2's zig-zag with more yaw damping than the
// vessel has (r' += -0.01 r): the alternative that adds that damping replays the zig-zag's
// overshoots; one that takes damping away overshoots further than the vessel does, and is
// never chosen, however low its free-run error. Without a zig-zag or turning circle among the
// records (a PRBS rudder) the model stays as fitted.
#include "metrics/closed_loop_choice.h"

#include <gtest/gtest.h>

#include "effects/effect.h"
#include "effects/effect_values.h"
#include "maneuvers/maneuver_factory.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

Effect YawDamping(double coefficient) {
  return {EffectKind::kMissingTerm, {{"coefficient", coefficient}}, {}, "r", "r"};
}

// kvlcc2's `spec` with r' += `extra` r, as a record at 5 Hz.
Dataset Record(const std::string& spec, double extra) {
  const VesselSimulator& sim = FindVessel("kvlcc2");
  const VesselInfo& info = sim.Info();
  auto m = MakeManeuver(spec, info.actuation, 400.0, 1);
  RunOptions at_5hz;
  at_5hz.rate_hz = 5.0;
  at_5hz.dt = 0.1;
  return sim
      .RunManeuver(*m, info.default_params, ValuesOf({YawDamping(extra)}, info.inputs, info.states),
                   at_5hz)
      .data;
}

nlohmann::json Alternative(const std::string& label, double coefficient, double free_run_error) {
  nlohmann::json effects = nlohmann::json::array();
  if (coefficient != 0.0) effects.push_back(EffectToJson(YawDamping(coefficient)));
  return {{"label", label},
          {"corrections", nlohmann::json::object()},
          {"effects", effects},
          {"free_run_error", free_run_error}};
}

// A grey-box model of kvlcc2 as GP writes it with --base, fitted by free runs to `kept`.
nlohmann::json GreyBoxModel() {
  return {{"method", "gp"},  // as GP writes it
          {"vessel", "kvlcc2"},
          {"states", {"u", "v", "r"}},
          {"parameters", nlohmann::json::object()},
          {"effects", Alternative("", 0.01, 0).at("effects")},  // the free runs' choice
          {"alternatives",
           {Alternative("vessel", 0.0, 1.0), Alternative("less damping", 0.01, 0.2),
            Alternative("more damping", -0.01, 0.5)}},
          {"calibration", {{"choose", "closed-loop"}}}};
}

TEST(ClosedLoopChoiceTest, KeepsTheCorrectionWhoseZigzagIsNoWorseThanTheVessels) {
  const Dataset record = Record("zigzag:20/20", -0.01);
  nlohmann::json model = GreyBoxModel();
  const nlohmann::json report = ChooseByClosedLoop(model, record, "");
  ASSERT_TRUE(report["applied"].get<bool>()) << report.dump();
  EXPECT_EQ(report["maneuvers"], nlohmann::json::array({"zigzag:20/20"}));
  EXPECT_EQ(report["chosen"], "more damping") << report.dump(1);
  EXPECT_EQ(model["effects"], Alternative("", -0.01, 0).at("effects"));
  // The premise: the vessel overshoots further than the record, the correction with less
  // damping further still (inadmissible), the right one replays it.
  const nlohmann::json& a = report["alternatives"];
  ASSERT_EQ(a.size(), 3u);
  const double vessel = a[0]["first_overshoot_error_deg"].get<double>();
  EXPECT_GT(vessel, 0.5) << a.dump(1);
  EXPECT_GT(a[1]["first_overshoot_error_deg"].get<double>(), vessel) << a.dump(1);
  EXPECT_FALSE(a[1]["admissible"].get<bool>());
  EXPECT_LT(a[2]["first_overshoot_error_deg"].get<double>(), 0.1) << a.dump(1);
}

TEST(ClosedLoopChoiceTest, TheVesselStaysWhenEveryCorrectionBendsTheTest) {
  const Dataset record = Record("zigzag:20/20", -0.01);
  nlohmann::json model = GreyBoxModel();
  model["alternatives"].erase(2);  // only the wrong correction left
  const nlohmann::json report = ChooseByClosedLoop(model, record, "");
  ASSERT_TRUE(report["applied"].get<bool>()) << report.dump();
  EXPECT_EQ(report["chosen"], "vessel");
  EXPECT_EQ(model["effects"], nlohmann::json::array());
}

TEST(ClosedLoopChoiceTest, WithoutAZigzagOrTurnAmongTheRecordsTheModelStaysAsFitted) {
  const Dataset record = Record("prbs", -0.01);  // a rudder that switches: no test
  nlohmann::json model = GreyBoxModel();
  const nlohmann::json before = model;
  const nlohmann::json report = ChooseByClosedLoop(model, record, "");
  EXPECT_FALSE(report["applied"].get<bool>()) << report.dump();
  EXPECT_EQ(model, before);
}

}  // namespace
}  // namespace usvid
