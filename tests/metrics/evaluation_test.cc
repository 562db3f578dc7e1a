// Scoring models (contract section 5): fit % as MATLAB's compare defines it, the free run of the
// true equations reproduces the simulator, and a model that blows up is stopped, reported as
// diverged, and still scored with finite numbers.
#include "metrics/evaluation.h"

#include <gtest/gtest.h>

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
  // domain.md section 2.2, solved for the accelerations, in full precision.
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
