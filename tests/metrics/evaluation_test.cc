// Scoring models (docs/data.md#metricsjson): fit % as MATLAB's compare defines it, the free
// run of the true equations reproduces the simulator, and a model that blows up is stopped,
// reported as diverged, and still scored with finite numbers.
#include "metrics/evaluation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <utility>
#include <vector>

#include "core/error.h"
#include "effects/effect.h"
#include "effects/effect_values.h"
#include "maneuvers/maneuver_factory.h"
#include "metrics/fit_metrics.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

class EvaluationTest : public ::testing::Test {
 protected:
  static Dataset Odin(const std::string& maneuver) {
    const VesselSimulator& sim = FindVessel("odin3dof");
    auto m = MakeManeuver(maneuver, sim.Info().actuation, 120.0, 4);
    return sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
  }
  // docs/model.md#odin3dof, solved for the accelerations, in full precision.
  static nlohmann::json TrueModel() {
    return {{"method", "truth"},
            {"states", {"u", "v", "r"}},
            {"inputs", {"tau_x", "tau_y", "tau_n"}},
            {"equations",
             {{"u", "(tau_x + 4935*v*r - (50 + 243*abs(u))*u) / 4935"},
              {"v", "(tau_y - 4935*u*r - (200 + 2000*abs(v))*v) / 4935"},
              {"r", "(tau_n - 1281*v - (1281 + 2975*abs(r))*r) / 20928"}}}};
  }
};

// 100 for a perfect match, 0 for the mean, and the textbook value for a known error.
TEST_F(EvaluationTest, FitPercentFollowsTheDefinition) {
  Eigen::VectorXd y(4), mean = Eigen::VectorXd::Constant(4, 2.5);
  y << 1, 2, 3, 4;
  EXPECT_DOUBLE_EQ(ScoreChannel(y, y).fit_percent, 100.0);
  EXPECT_NEAR(ScoreChannel(y, mean).fit_percent, 0.0, 1e-12);
  const Eigen::VectorXd off = y.array() + 0.5;
  // ||e|| = 1, ||y - mean|| = sqrt(5): fit = 100 (1 - 1 / sqrt 5).
  EXPECT_NEAR(ScoreChannel(y, off).fit_percent, 100.0 * (1.0 - 1.0 / std::sqrt(5.0)), 1e-12);
  EXPECT_NEAR(ScoreChannel(y, off).rmse, 0.5, 1e-12);
  // A channel held constant, but for rounding (an rpm of 1500 through a zig-zag), has no
  // variance: a model off its level scores 0, not -1e13 %.
  Eigen::VectorXd held = Eigen::VectorXd::Constant(4, 1500.0);
  held(2) += 1e-10;
  const ChannelScore flat = ScoreChannel(held, held.array() + 2.0);
  EXPECT_EQ(flat.fit_percent, 0.0);
  EXPECT_EQ(flat.nrmse, 0.0);
  EXPECT_NEAR(flat.rmse, 2.0, 1e-9);
}

// A suite's rows need no k-step NRMSE and a plot only the free run: the narrower scopes leave
// that out and change nothing else, to the bit.
TEST_F(EvaluationTest, NarrowerScopesComputeTheSameScoresWithoutTheRest) {
  nlohmann::json model = TrueModel();
  model["equations"]["u"] = "0.99*(" + model["equations"]["u"].get<std::string>() + ")";
  const Dataset d = Odin("random-steps");
  const Evaluation all = EvaluateModel(model, d);
  const Evaluation rows = EvaluateModel(model, d, EvaluationScope::kRowScores);
  const Evaluation plot = EvaluateModel(model, d, EvaluationScope::kFreeRunOnly);
  nlohmann::json expected = all.metrics;
  expected["k_step_nrmse"] = nlohmann::json::object();
  EXPECT_FALSE(all.metrics.at("k_step_nrmse").empty());
  EXPECT_EQ(rows.metrics.dump(), expected.dump());
  EXPECT_TRUE(plot.metrics.is_null());
  for (const std::string& c : all.run.channels)
    EXPECT_EQ(plot.run.simulated[c], all.run.simulated[c]) << c;
}

// The true equations, free-run on the simulator's inputs, give back the simulator's run,
// positions and heading included (the kinematics of the free run are right).
TEST_F(EvaluationTest, TrueEquationsReproduceTheSimulator) {
  const Dataset d = Odin("random-steps");
  const Evaluation e = EvaluateModel(TrueModel(), d);
  EXPECT_FALSE(e.metrics.at("diverged").get<bool>());
  for (const char* c : {"u", "v", "r", "psi", "north", "east"})
    EXPECT_GT(e.metrics.at(c).at("fit_percent").get<double>(), 99.99) << c;
  EXPECT_LT(e.metrics.at("position_drift_m").get<double>(), 0.01);
  EXPECT_GT(e.metrics.at("derivative_r2").at("u").get<double>(), 0.99);
  // k steps ahead from measured states: the true model stays on the data.
  for (const char* k : {"10", "40"})
    EXPECT_LT(e.metrics.at("k_step_nrmse").at(k).at("r").get<double>(), 1e-3) << k;
  // Scores per speed regime, over the rows measured in each (odin3dof reaches all three).
  const auto& regimes = e.metrics.at("regimes");
  EXPECT_FALSE(regimes.empty());
  long rows = 0;
  for (const auto& [name, scores] : regimes.items()) {
    rows += scores.at("samples").get<long>();
    EXPECT_GT(scores.at("u").at("fit_percent").get<double>(), 99.9) << name;
  }
  EXPECT_LE(rows, d.rows());
}

// u' = u grows without bound: stopped at the bound, diverged, finite scores.
TEST_F(EvaluationTest, DivergentModelIsStoppedAndScored) {
  nlohmann::json model = TrueModel();
  model["equations"]["u"] = "0.5*u";
  const Evaluation e = EvaluateModel(model, Odin("multisine"));
  EXPECT_TRUE(e.metrics.at("diverged").get<bool>());
  EXPECT_GT(e.metrics.at("diverged_at_s").get<double>(), 0.0);
  for (const char* c : {"u", "v", "r"})
    EXPECT_TRUE(std::isfinite(e.metrics.at(c).at("fit_percent").get<double>())) << c;
  // Short horizons from measured states still score it, and worse than the truth would.
  EXPECT_GT(e.metrics.at("k_step_nrmse").at("40").at("u").get<double>(), 1e-2);
  EXPECT_EQ(e.metrics.dump().find("null"), std::string::npos);
}

// A broken equation or a missing channel is bad input that names itself.
TEST_F(EvaluationTest, BadModelsAreRefused) {
  nlohmann::json model = TrueModel();
  model["equations"]["u"] = "(tau_x + ";
  EXPECT_THROW(EvaluateModel(model, Odin("prbs")), InputError);
  model = TrueModel();
  model["equations"]["u"] = "tau_q";
  EXPECT_THROW(EvaluateModel(model, Odin("prbs")), InputError);
  EXPECT_THROW(EvaluateModel(nlohmann::json::object(), Odin("prbs")), InputError);
}

// A vessel model (no equations; refit, nominal and diagnose write them) is free-run by the
// vessel itself, with its parameters and effects: the simulator that made the data reproduces
// them, a current it lacks shows, the current in the model's effects closes the gap.
TEST_F(EvaluationTest, VesselModelsRunTheirSimulator) {
  const VesselSimulator& sim = FindVessel("odin3dof");
  const Effect current{EffectKind::kCurrent, {{"current_north", 0.4}, {"current_east", 0.0}}};
  auto m = MakeManeuver("zigzag:20/20", sim.Info().actuation, 120.0, 4);
  const Dataset data =
      sim.RunManeuver(*m, sim.Info().default_params, ValuesOf({current}), RunOptions{}).data;
  nlohmann::json model = {{"method", "nominal"}, {"vessel", "odin3dof"}};
  const Evaluation nominal = EvaluateModel(model, data);
  EXPECT_LT(nominal.metrics.at("north").at("fit_percent").get<double>(), 99.0);
  model["effects"] = nlohmann::json::array({EffectToJson(current)});
  const Evaluation extended = EvaluateModel(model, data);
  for (const char* c : {"u", "v", "r", "psi", "north", "east"})
    EXPECT_GT(extended.metrics.at(c).at("fit_percent").get<double>(), 99.9) << c;
  EXPECT_FALSE(extended.metrics.at("diverged").get<bool>());
}

TEST_F(EvaluationTest, BadVesselModelsAreRefused) {
  const Dataset data = Odin("zigzag:20/20");
  EXPECT_THROW(EvaluateModel({{"vessel", "titanic"}}, data), InputError);
  EXPECT_THROW(EvaluateModel({{"vessel", "odin3dof"}, {"parameters", {{"warp", 9}}}}, data),
               InputError);
  EXPECT_THROW(
      EvaluateModel({{"vessel", "odin3dof"}, {"effects", {{{"effect", "current"}}}}}, data),
      InputError);
  EXPECT_THROW(EvaluateModel({{"vessel", "odin3dof"},
                              {"effects", {{{"effect", "inertia"}, {"parameters", {{"sc", 1}}}}}}},
                             data),
               InputError);
}

}  // namespace
}  // namespace usvid

namespace usvid {
namespace {

// Records for the tests below: a vessel's noise-free run, and a record written channel by
// channel as functions of time (10 Hz).
Dataset Simulated(const std::string& vessel, const std::string& maneuver, double duration_s) {
  const VesselSimulator& sim = FindVessel(vessel);
  auto m = MakeManeuver(maneuver, sim.Info().actuation, duration_s, 4);
  return sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
}

Dataset Written(double duration_s,
                const std::vector<std::pair<std::string, std::function<double(double)>>>& of_t) {
  const auto rows = static_cast<Eigen::Index>(std::lround(duration_s / 0.1)) + 1;
  Dataset d(Eigen::VectorXd::LinSpaced(rows, 0.0, duration_s));
  for (const auto& [name, f] : of_t) d.Set(name, d.t().unaryExpr(f));
  return d;
}

// The msd's equation (docs/model.md#msd, x'' = (f - d x' - k x) / m) with damping d.
nlohmann::json MsdModel(double damping) {
  return {{"method", "truth"},
          {"states", {"v"}},
          {"variables", {"x", "v"}},
          {"inputs", {"f"}},
          {"equations", {{"v", "(f - " + std::to_string(damping) + "*v - 2*x) / 10"}}}};
}

// A vessel model of `vessel` with its damping scaled.
nlohmann::json DampedVesselModel(const std::string& vessel, double scale) {
  const Effect damping{EffectKind::kDamping, {{"scale", scale}}};
  return {{"vessel", vessel}, {"effects", nlohmann::json::array({EffectToJson(damping)})}};
}

// Divergence is per channel: sway that grows as v' = 2 v from 0.1 m/s, on a record whose |v|
// never exceeds 0.1 m/s, is stopped when it passes 10 x 0.1 = 1 m/s (0.1 e^(2t) = 1 at
// t = ln(10) / 2 = 1.15 s, so at the 1.2 s sample), reported as "v", and held at its last value
// in bound. The old single bound, ten times the largest magnitude of any channel (north up to
// 1300 m here), would have let it reach 13000 m/s first, at t = ln(130000) / 2 = 5.9 s.
TEST_F(EvaluationTest, GrowingSwayDivergesAtItsOwnBound) {
  const Dataset data = Written(60.0, {{"u", [](double) { return 5.0; }},
                                      {"v", [](double t) { return 0.1 * std::cos(0.5 * t); }},
                                      {"r", [](double) { return 0.0; }},
                                      {"psi", [](double) { return 0.0; }},
                                      {"north", [](double t) { return 1000.0 + 5.0 * t; }},
                                      {"east", [](double) { return 0.0; }}});
  const nlohmann::json model = {{"equations", {{"u", "0*u"}, {"v", "2*v"}, {"r", "0*r"}}}};
  const FreeRun run = FreeRunModel(model, data);
  ASSERT_TRUE(run.diverged);
  EXPECT_EQ(run.diverged_channel, "v");
  EXPECT_NEAR(run.diverged_at_s, 1.2, 1e-9);
  const Eigen::VectorXd& v = run.simulated["v"];
  EXPECT_NEAR(v(11), 0.1 * std::exp(2.0 * 1.1), 1e-6);  // in bound at 1.1 s
  EXPECT_EQ(v(v.size() - 1), v(11));                    // held from there on
  const DivergenceBounds bounds(run.channels, data);
  const auto at = [&](const char* c) {
    return static_cast<size_t>(std::ranges::find(run.channels, c) - run.channels.begin());
  };
  EXPECT_NEAR(bounds.Bound(at("v")), 1.0, 1e-12);
  EXPECT_NEAR(bounds.Bound(at("u")), 50.0, 1e-12);
  EXPECT_NEAR(bounds.Bound(at("r")), 1e-2, 1e-15);  // a channel held at zero: 10 x 1e-3
  for (const char* c : {"psi", "north", "east"}) EXPECT_TRUE(std::isinf(bounds.Bound(at(c)))) << c;
  // The metrics name the channel too.
  const Evaluation e = EvaluateModel(model, data);
  EXPECT_TRUE(e.metrics.at("diverged").get<bool>());
  EXPECT_EQ(e.metrics.at("diverged_channel"), "v");
  EXPECT_NEAR(e.metrics.at("diverged_at_s").get<double>(), 1.2, 1e-9);
}

// Heading and positions are integrals of the velocities, only checked for finiteness: a model
// turning in circles at a steady 0.2 rad/s for 300 s winds its heading up to 60 rad, 19 times the
// largest heading the (wrapped) record shows, and is not diverged.
TEST_F(EvaluationTest, ModelTurningInCirclesIsNotDiverged) {
  const Dataset data = Written(
      300.0, {{"u", [](double) { return 5.0; }},
              {"v", [](double) { return 0.0; }},
              {"r", [](double) { return 0.2; }},
              {"psi", [](double t) { return std::remainder(0.2 * t, 2 * std::numbers::pi); }},
              {"north", [](double t) { return 25.0 * std::sin(0.2 * t); }},
              {"east", [](double t) { return 25.0 * (1 - std::cos(0.2 * t)); }}});
  const nlohmann::json model = {{"equations", {{"u", "0*u"}, {"v", "-v"}, {"r", "0*r"}}}};
  const FreeRun run = FreeRunModel(model, data);
  EXPECT_FALSE(run.diverged);
  EXPECT_TRUE(run.diverged_channel.empty());
  const Eigen::VectorXd& psi = run.simulated["psi"];
  EXPECT_NEAR(psi(psi.size() - 1), 60.0, 1e-6);
  EXPECT_GT(std::abs(psi(psi.size() - 1)), 10 * data["psi"].cwiseAbs().maxCoeff());
  // The circle itself is integrated right: radius u / r = 25 m about (0, 25).
  EXPECT_NEAR(run.simulated["north"](1500), 25.0 * std::sin(30.0), 1e-6);
  const Evaluation e = EvaluateModel(model, data);
  EXPECT_FALSE(e.metrics.at("diverged").get<bool>());
  EXPECT_FALSE(e.metrics.contains("diverged_channel"));
}

// Prediction horizons: the true model (the msd's exact equation, or the nominal odin3dof
// simulator that made the noise-free data) fits every horizon to > 99 %. With the damping 30 %
// low, restarting from the measured state every H seconds bounds how far the error grows: the
// 5 s horizon fits better than the 30 s one, which fits at least as well as the free run ("all").
TEST_F(EvaluationTest, ShortHorizonsBoundTheErrorGrowthOfAWrongModel) {
  const Dataset msd = Simulated("msd", "random-steps", 180.0);
  const Dataset odin = Simulated("odin3dof", "random-steps", 180.0);
  const std::pair<const Dataset*, nlohmann::json> truths[] = {{&msd, MsdModel(1.0)},
                                                              {&odin, {{"vessel", "odin3dof"}}}};
  const std::pair<const Dataset*, nlohmann::json> wrongs[] = {
      {&msd, MsdModel(0.7)}, {&odin, DampedVesselModel("odin3dof", 0.7)}};
  for (const auto& [data, model] : truths) {
    const auto fits = EvaluateModel(model, *data).metrics.at("horizon_fit_percent");
    for (const char* h : {"5", "30", "all"})
      for (const auto& [c, fit] : fits.at(h).items())
        EXPECT_GT(fit.get<double>(), 99.0) << model.dump() << " " << h << " " << c;
  }
  for (const auto& [data, model] : wrongs) {
    const auto fits = EvaluateModel(model, *data).metrics.at("horizon_fit_percent");
    ASSERT_FALSE(fits.at("all").empty());
    for (const auto& [c, all] : fits.at("all").items()) {
      const double fit5 = fits.at("5").at(c), fit30 = fits.at("30").at(c);
      EXPECT_GT(fit5, fit30) << model.dump() << " " << c;
      EXPECT_GE(fit30, all.get<double>()) << model.dump() << " " << c;
      EXPECT_LT(fit5, 99.0) << model.dump() << " " << c;  // the error shows at 5 s too
    }
  }
  // An endless horizon is one window from the first row: the free run.
  EXPECT_EQ(HorizonKey(INFINITY), "all");
  EXPECT_EQ(HorizonKey(30.0), "30");
  const auto endless = HorizonFit(MsdModel(0.7), msd, INFINITY);
  const FreeRun run = FreeRunModel(MsdModel(0.7), msd);
  for (const char* c : {"x", "v"})
    EXPECT_NEAR(endless.at(c), ScoreChannel(msd[c], run.simulated[c]).fit_percent, 1e-9) << c;
}

// The horizons scored are those shorter than the record: "5", "30" and "all" for 180 s, and no
// "30" for 20 s.
TEST_F(EvaluationTest, HorizonsShorterThanTheRecordAreScored) {
  const auto keys = [](const nlohmann::json& fits) {
    std::vector<std::string> k;
    for (const auto& [key, _] : fits.items()) k.push_back(key);
    std::ranges::sort(k);
    return k;
  };
  const auto long_fits = EvaluateModel(MsdModel(1.0), Simulated("msd", "multisine", 180.0))
                             .metrics.at("horizon_fit_percent");
  EXPECT_EQ(keys(long_fits), (std::vector<std::string>{"30", "5", "all"}));
  const auto short_fits = EvaluateModel(MsdModel(1.0), Simulated("msd", "multisine", 20.0))
                              .metrics.at("horizon_fit_percent");
  EXPECT_EQ(keys(short_fits), (std::vector<std::string>{"5", "all"}));
  for (const char* c : {"x", "v"}) EXPECT_GT(short_fits.at("5").at(c).get<double>(), 99.0) << c;
}

// valid_prediction_s: the true model's free run never leaves the record by more than
// kValidPredictionError standard deviations, so it is valid for the whole record; one with the
// damping 30 % low drifts off sooner.
TEST_F(EvaluationTest, ValidPredictionTimeIsTheRecordForTheTruthAndShorterForADriftingModel) {
  for (const char* vessel : {"msd", "odin3dof"}) {
    const Dataset data = Simulated(vessel, "random-steps", 180.0);
    const nlohmann::json truth =
        std::string(vessel) == "msd" ? MsdModel(1.0) : nlohmann::json{{"vessel", vessel}};
    const nlohmann::json drifting =
        std::string(vessel) == "msd" ? MsdModel(0.7) : DampedVesselModel(vessel, 0.7);
    EXPECT_DOUBLE_EQ(EvaluateModel(truth, data).metrics.at("valid_prediction_s").get<double>(),
                     data.duration())
        << vessel;
    const double drift = EvaluateModel(drifting, data).metrics.at("valid_prediction_s");
    EXPECT_GT(drift, 0.0) << vessel;
    EXPECT_LT(drift, 0.75 * data.duration()) << vessel;
  }
}

// A vessel model is held to the same per-channel bounds as an equation model, not only to its
// simulator's 1e7: the msd with its damping scaled by -5 (x'' = (f + 5 x' - 2 x) / 10) on a
// 180 s random-steps record (|v| <= 3.65 m/s, bound 36.5 m/s) is stopped where v leaves its
// bound, as the equivalent equation model is, and held there.
TEST_F(EvaluationTest, DivergingVesselModelIsStoppedAtItsChannelBound) {
  const Dataset data = Simulated("msd", "random-steps", 180.0);
  const FreeRun equations = FreeRunModel(MsdModel(-5.0), data);
  ASSERT_TRUE(equations.diverged);
  ASSERT_EQ(equations.diverged_channel, "v");
  const FreeRun vessel = FreeRunModel(DampedVesselModel("msd", -5.0), data);
  ASSERT_TRUE(vessel.diverged);
  EXPECT_EQ(vessel.diverged_channel, "v");
  EXPECT_NEAR(vessel.diverged_at_s, equations.diverged_at_s, 0.1);
  const DivergenceBounds bounds(vessel.channels, data);
  for (size_t i = 0; i < vessel.channels.size(); ++i)
    EXPECT_LE(vessel.simulated[vessel.channels[i]].cwiseAbs().maxCoeff(), bounds.Bound(i))
        << vessel.channels[i];
}

}  // namespace
}  // namespace usvid
