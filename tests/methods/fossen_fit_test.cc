// fossen-ceres (issue 6 acceptance): on odin3dof random steps the simulation-error fit
// (multiple shooting through the templated simulator) recovers every parameter within 0.5 %
// without noise and within 5 % at 2 % noise, where it beats the equation-error fit; the fitted
// model free-runs a held-out multisine run at a fit of 98 % or more on u, v and r.
#include "methods/fossen_ceres/fossen_fit.h"

#include <gtest/gtest.h>

#include "maneuvers/maneuver_factory.h"
#include "metrics/evaluation.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"
#include "simulators/odin3dof.h"

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
  const fossen::FossenFit eq = fossen::FitEquationError(prep, o);
  const fossen::FossenFit sim = fossen::FitSimulationError(prep, eq.params, o);
  EXPECT_TRUE(sim.converged) << sim.termination;
  EXPECT_LE(WorstError(sim.params), 0.005);
}

TEST_F(FossenFitTest, TwoPercentNoiseSimulationErrorBeatsEquationError) {
  const PreparedData prep = Prepare(Simulate("random-steps", 600, 0.02, 5));
  const fossen::FossenOptions o;
  const fossen::FossenFit eq = fossen::FitEquationError(prep, o);
  const fossen::FossenFit sim = fossen::FitSimulationError(prep, eq.params, o);
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
  const fossen::FossenFit fit =
      fossen::FitSimulationError(prep, fossen::FitEquationError(prep, o).params, o);
  const nlohmann::json model = {{"states", {"u", "v", "r"}},
                                {"inputs", {"tau_x", "tau_y", "tau_n"}},
                                {"equations", fossen::Equations(fit.params)}};
  const Evaluation e = EvaluateModel(model, Simulate("multisine", 300, 0.0, 77));
  for (const char* c : {"u", "v", "r"})
    EXPECT_GE(e.metrics.at(c).at("fit_percent").get<double>(), 98.0) << c;
}

}  // namespace
}  // namespace usvid
