// fossen-ceres (issue 6 acceptance): on odin3dof random steps the simulation-error fit
// (multiple shooting through the templated simulator) recovers every parameter within 0.5 %
// without noise and within 5 % at 2 % noise, where it beats the equation-error fit; the fitted
// model free-runs a held-out multisine run at a fit of 98 % or more on u, v and r. The waterjet
// input map fits odin-hs from throttle, nozzle and bucket.
#include "methods/fossen_ceres/fossen_fit.h"

#include <gtest/gtest.h>

#include "maneuvers/maneuver_factory.h"
#include "methods/fossen_ceres/fossen_models.h"
#include "metrics/evaluation.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"
#include "simulators/odin3dof.h"
#include "tests/support/synthetic_data.h"

namespace usvid {
namespace {

class FossenFitTest : public ::testing::Test {
 protected:
  static Dataset Simulate(const std::string& maneuver, double seconds, double noise,
                          uint64_t seed) {
    const VesselSimulator& sim = FindVessel("odin3dof");
    auto m = MakeManeuver(maneuver, sim.Info().actuation, seconds, seed);
    Dataset d = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
    AddGaussianNoise(d, sim.Info().states, noise, seed);
    return d;
  }
  static PreparedData Prepare(const Dataset& d) {
    return Preprocess(d, {"u", "v", "r"}, {"tau_x", "tau_y", "tau_n"}, {});
  }
  // Largest |relative error| over the parameters.
  static double WorstError(const std::array<double, 10>& p) {
    double worst = 0.0;
    for (int i = 0; i < 10; ++i)
      worst = std::max(worst, std::abs(p[i] / Odin3Dof::kDefaultParams[i] - 1.0));
    return worst;
  }
};

TEST_F(FossenFitTest, NoiseFreeRecoversEveryParameterWithinHalfAPercent) {
  const PreparedData prep = Prepare(Simulate("random-steps", 600, 0.0, 5));
  const fossen::FossenOptions o;
  const fossen::FossenFit eq = fossen::FitEquationErrorFor<fossen::Odin3DofModel>(prep, o);
  const fossen::FossenFit sim =
      fossen::FitSimulationErrorFor<fossen::Odin3DofModel>(prep, eq.params, o);
  EXPECT_TRUE(sim.converged) << sim.termination;
  EXPECT_LE(WorstError(sim.params), 0.005);
}

TEST_F(FossenFitTest, TwoPercentNoiseSimulationErrorBeatsEquationError) {
  const PreparedData prep = Prepare(Simulate("random-steps", 600, 0.02, 5));
  const fossen::FossenOptions o;
  const fossen::FossenFit eq = fossen::FitEquationErrorFor<fossen::Odin3DofModel>(prep, o);
  const fossen::FossenFit sim =
      fossen::FitSimulationErrorFor<fossen::Odin3DofModel>(prep, eq.params, o);
  EXPECT_LE(WorstError(sim.params), 0.05);
  EXPECT_LT(WorstError(sim.params), WorstError(eq.params));
  EXPECT_TRUE(sim.covariance_ok);
  // The reported standard deviations are of the size of the actual errors.
  for (int i = 0; i < 10; ++i)
    EXPECT_LT(std::abs(sim.params[i] - Odin3Dof::kDefaultParams[i]), 6 * sim.sd[i] + 1e-9)
        << Odin3Dof::kParamNames[i];
}

TEST_F(FossenFitTest, FreeRunsHeldOutMultisineAtNinetyEightPercent) {
  const PreparedData prep = Prepare(Simulate("random-steps", 600, 0.005, 5));
  const fossen::FossenOptions o;
  const fossen::FossenFit fit = fossen::FitSimulationErrorFor<fossen::Odin3DofModel>(
      prep, fossen::FitEquationErrorFor<fossen::Odin3DofModel>(prep, o).params, o);
  const nlohmann::json model = {
      {"states", {"u", "v", "r"}},
      {"inputs", {"tau_x", "tau_y", "tau_n"}},
      {"equations", fossen::EquationsFor<fossen::Odin3DofModel>(fit.params)}};
  const Evaluation e = EvaluateModel(model, Simulate("multisine", 300, 0.0, 77));
  for (const char* c : {"u", "v", "r"})
    EXPECT_GE(e.metrics.at(c).at("fit_percent").get<double>(), 98.0) << c;
}

// odin-hs through the waterjet input map (no actuator dynamics, so no high fit is expected): both
// fits end in Ceres convergence with finite positive parameters, multiple shooting lowers the
// segment cost of the equation-error start, and the held-out free run scores a finite fit.
TEST_F(FossenFitTest, WaterjetMapFitsOdinHsFromThrottleNozzleAndBucket) {
  const std::vector<std::string> inputs = {"throttle", "nozzle", "bucket"};
  PreprocessOptions pre;
  pre.rate_hz = 5.0;  // seconds-long dynamics: 5 Hz keeps the run time short
  const PreparedData prep = Preprocess(testing::Simulate("odin-hs", "random-steps", 600, 0.005, 5),
                                       {"u", "v", "r"}, inputs, pre);
  fossen::FossenOptions o;
  o.function_tolerance = 1e-6;  // Ceres' default: the misspecified model creeps on for long
  const fossen::BasicFossenFit<13> eq = fossen::FitEquationErrorFor<fossen::WaterjetModel>(prep, o);
  EXPECT_TRUE(eq.converged) << eq.termination;
  const fossen::BasicFossenFit<13> sim =
      fossen::FitSimulationErrorFor<fossen::WaterjetModel>(prep, eq.params, o);
  EXPECT_TRUE(sim.converged) << sim.termination;
  EXPECT_LT(sim.final_cost, 0.5 * sim.initial_cost);
  for (int i = 0; i < fossen::WaterjetModel::kParams; ++i) {
    EXPECT_TRUE(std::isfinite(eq.params[i]) && eq.params[i] > 0) << i;
    EXPECT_TRUE(std::isfinite(sim.params[i]) && sim.params[i] > 0) << i;
    std::printf("%-4s equation error %12.5g  simulation error %12.5g\n",
                std::string(fossen::WaterjetModel::kParamNames[i]).c_str(), eq.params[i],
                sim.params[i]);
  }
  std::printf("equation error: cost %.6g -> %.6g, %d iterations, %.2f s, %s\n", eq.initial_cost,
              eq.final_cost, eq.iterations, eq.seconds, eq.termination.c_str());
  std::printf("simulation error: cost %.6g -> %.6g, %d iterations, %.2f s, %s\n", sim.initial_cost,
              sim.final_cost, sim.iterations, sim.seconds, sim.termination.c_str());
  const nlohmann::json model = {
      {"states", {"u", "v", "r"}},
      {"inputs", inputs},
      {"equations", fossen::EquationsFor<fossen::WaterjetModel>(sim.params)}};
  const Evaluation e =
      EvaluateModel(model, testing::Simulate("odin-hs", "random-steps", 600, 0.0, 77));
  for (const char* c : {"u", "v", "r"}) {
    const double fit = e.metrics.at(c).at("fit_percent").get<double>();
    EXPECT_TRUE(std::isfinite(fit)) << c;
    std::printf("held-out free run fit %s: %.1f %%\n", c, fit);
  }
}

// On a record longer than max_rows, both fits use a bounded share of it spread over the whole
// (Ceres holds the Jacobian of every residual it is given), and that share still recovers every
// parameter of the noise-free hull.
TEST_F(FossenFitTest, ABoundedShareOfALongRecordRecoversEveryParameter) {
  const PreparedData prep = Prepare(Simulate("random-steps", 1800, 0.0, 6));
  ASSERT_GT(prep.data.rows(), 30000);
  fossen::FossenOptions o;
  o.max_rows = 6000;
  const fossen::FossenFit eq = fossen::FitEquationErrorFor<fossen::Odin3DofModel>(prep, o);
  const fossen::FossenFit sim =
      fossen::FitSimulationErrorFor<fossen::Odin3DofModel>(prep, eq.params, o);
  for (const fossen::FossenFit* f : {&eq, &sim}) {
    EXPECT_LE(f->rows, 6000 + 200);  // at most one segment's rows over
    EXPECT_GE(f->rows, 6000 - 200);
  }
  EXPECT_TRUE(sim.converged) << sim.termination;
  EXPECT_LE(WorstError(sim.params), 0.005);
  o.max_rows = 0;  // all
  EXPECT_EQ(fossen::FitEquationErrorFor<fossen::Odin3DofModel>(prep, o).rows, prep.data.rows());
}

// A fit that Ceres stops before it converges says so and why (issue 11): not converged, the
// termination type and Ceres' message in the result, the parameters finite.
TEST_F(FossenFitTest, AFitStoppedEarlySaysWhy) {
  const PreparedData prep = Prepare(Simulate("random-steps", 120, 0.005, 5));
  fossen::FossenOptions o;
  o.max_iterations = 1;
  const fossen::FossenFit eq = fossen::FitEquationErrorFor<fossen::Odin3DofModel>(prep, o);
  const fossen::FossenFit sim =
      fossen::FitSimulationErrorFor<fossen::Odin3DofModel>(prep, eq.params, o);
  EXPECT_FALSE(sim.converged);
  EXPECT_NE(sim.termination.find("NO_CONVERGENCE"), std::string::npos) << sim.termination;
  EXPECT_NE(sim.termination.find("Maximum number of iterations"), std::string::npos)
      << sim.termination;
  for (double p : sim.params) EXPECT_TRUE(std::isfinite(p));
}

}  // namespace
}  // namespace usvid
