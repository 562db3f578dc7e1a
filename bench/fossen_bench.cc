// fossen-ceres speed (issue 6 and 10): the multiple-shooting fit of odin3dof's 10 parameters
// (plus 3 initial velocities per 10 s segment) on 18k samples (900 s at 20 Hz), one core,
// starting from the equation-error fit; and the equation-error fit itself.
#include <benchmark/benchmark.h>

#include "maneuvers/maneuver_factory.h"
#include "methods/fossen_ceres/fossen_fit.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

const PreparedData& Data18k() {
  static const PreparedData prepared = [] {
    const VesselSimulator& sim = FindVessel("odin3dof");
    auto m = MakeManeuver("random-steps", sim.Info().actuation, 900.0, 5);
    Dataset d = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
    AddGaussianNoise(d, sim.Info().states, 0.005, 5);
    return Preprocess(d, {"u", "v", "r"}, {"tau_x", "tau_y", "tau_n"}, {});
  }();
  return prepared;
}

void BM_FossenEquationError(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(fossen::FitEquationError(Data18k(), {}));
  state.counters["samples"] = static_cast<double>(Data18k().data.rows());
}
BENCHMARK(BM_FossenEquationError)->Unit(benchmark::kMillisecond);

void BM_FossenMultipleShooting(benchmark::State& state) {
  const auto start = fossen::FitEquationError(Data18k(), {}).params;
  fossen::FossenFit fit;
  for (auto _ : state) fit = fossen::FitSimulationError(Data18k(), start, {});
  state.counters["samples"] = static_cast<double>(Data18k().data.rows());
  state.counters["iterations"] = fit.iterations;
}
BENCHMARK(BM_FossenMultipleShooting)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace usvid
