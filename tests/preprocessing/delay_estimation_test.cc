// Input delay from data (issue 4 acceptance): 0.5 s on the msd sampled at 100 Hz found within
// one sample, and 0.3 to 1.0 s on odin3dof at 20 Hz with 1 % noise within one sample, where the
// reference report's scan failed (its Fig. 3.14): by the report's own brute-force scan made
// right (derivatives without lag, a library with the |x|x terms), by cross-correlation, and by
// a continuous NLopt search on the simulation error.
#include "preprocessing/delay_estimation.h"

#include <gtest/gtest.h>

#include "maneuvers/maneuver_factory.h"
#include "preprocessing/derivative.h"
#include "sensors/noise.h"
#include "simulation/segment_error.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

class DelayEstimationTest : public ::testing::Test {
 protected:
  static Dataset Simulate(const std::string& vessel, const std::string& maneuver, double delay,
                          double rate_hz, double noise, uint64_t seed) {
    const VesselSimulator& sim = FindVessel(vessel);
    auto m = MakeManeuver(maneuver, sim.Info().actuation, 600.0, seed);
    RunOptions opt;
    opt.rate_hz = rate_hz;
    EffectValues<double> e;
    e.delay_s = delay;
    Dataset d = sim.RunManeuver(*m, sim.Info().default_params, e, opt).data;
    AddGaussianNoise(d, sim.Info().states, noise, seed);
    return d;
  }

  static DelayProblem Problem(const Dataset& d, const std::vector<std::string>& states,
                              const std::vector<std::string>& inputs) {
    DelayProblem p;
    p.dt = d.t()(1) - d.t()(0);
    const DerivativeMethod method;  // the default estimator
    for (const std::string& s : states) {
      const SmoothedSignal sm = SmoothAndDifferentiate(d[s], p.dt, method);
      p.states.push_back({s, sm.value});
      p.derivatives.push_back({s + "_dot", sm.derivative});
    }
    for (const std::string& u : inputs) p.inputs.push_back({u, d[u]});
    return p;
  }
};

TEST_F(DelayEstimationTest, MsdHalfSecondWithinOneSample) {
  const Dataset d = Simulate("msd", "random-steps", 0.5, 100.0, 0.01, 1);
  const DelayProblem p = Problem(d, {"x", "v"}, {"f"});
  const DelayEstimate scan = ScanDelay(p, 2.0);
  EXPECT_NEAR(scan.delay_s, 0.5, 0.01);
  const DelayEstimate xcorr = CrossCorrelationDelay(p, 2.0);
  EXPECT_NEAR(xcorr.delay_s, 0.5, 0.01);
}

TEST_F(DelayEstimationTest, Odin3DofDelaysWithinOneSample) {
  int seed = 1;
  for (const double delay : {0.3, 0.55, 0.8, 1.0}) {
    const Dataset d = Simulate("odin3dof", "random-steps", delay, 20.0, 0.01, ++seed);
    const DelayProblem p = Problem(d, {"u", "v", "r"}, {"tau_x", "tau_y", "tau_n"});
    const DelayEstimate scan = ScanDelay(p, 2.0);
    EXPECT_NEAR(scan.delay_s, delay, 0.05) << "scan, true delay " << delay;
    const DelayEstimate per_input = ScanDelay(p, 2.0, true);
    for (double di : per_input.per_input_s) EXPECT_NEAR(di, delay, 0.05) << "per input";
    const DelayEstimate xcorr = CrossCorrelationDelay(p, 2.0);
    EXPECT_NEAR(xcorr.delay_s, delay, 0.05) << "cross-correlation, true delay " << delay;
  }
}

// The continuous estimate: NLopt on the segmented simulation error of the nominal model.
TEST_F(DelayEstimationTest, ContinuousSimulationErrorFindsTheDelay) {
  const VesselSimulator& sim = FindVessel("odin3dof");
  const double delay = 0.65;
  const Dataset d = Simulate("odin3dof", "random-steps", delay, 20.0, 0.01, 9);
  auto cost = [&](const std::vector<double>& x) {
    EffectValues<double> e;
    e.delay_s = x[0];
    return SegmentedSimulationError(sim, sim.Info().default_params, e, d, {"u", "v", "r"}, 10.0);
  };
  const DelayEstimate est = ContinuousDelay(cost, 1, 2.0, {0.0}, 60);
  EXPECT_NEAR(est.delay_s, delay, 0.05);
}

}  // namespace
}  // namespace usvid
