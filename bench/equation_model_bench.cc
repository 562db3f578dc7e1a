// The free run of an equation model (GP's and SINDy's model.json) over 600 s of an odin3dof
// zig-zag at 0.01 s RK4 steps, as compare's scores run it on every held-out maneuver: most of
// `compare --quick`'s time went to these runs (docs/performance.md#the-default-compare-issue-36).
#include <benchmark/benchmark.h>

#include <nlohmann/json.hpp>

#include "maneuvers/maneuver_factory.h"
#include "metrics/free_run.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

void BM_EquationModelFreeRun600s(benchmark::State& state) {
  const VesselSimulator& sim = FindVessel("odin3dof");
  const auto maneuver = MakeManeuver("zigzag:20/20", sim.Info().actuation, 600.0, 1);
  const Dataset data =
      sim.RunManeuver(*maneuver, sim.Info().default_params, {}, RunOptions{}).data;
  // Equations of the size GP finds on odin3dof (four or five terms each, abs among the
  // operators), with odin3dof's steady surge speed and turn rate.
  const nlohmann::json model = {
      {"equations",
       {{"u", "1e-4*tau_x - 0.025*abs(u)*u + 0.02*v*r - 0.001*abs(v)*u"},
        {"v", "-0.5*v - 0.1*u*r + 0.01*abs(v)*v - 1e-6*tau_n + 0.01*abs(r)*v"},
        {"r", "-0.8*r + 1e-4*tau_n - 0.01*v*u + 0.02*abs(r)*r - 0.001*abs(v)*r"}}}};
  if (FreeRunModel(model, data).diverged) {
    state.SkipWithError("the benchmark's model diverged: it would time a short run");
    return;
  }
  for (auto _ : state) {
    const FreeRun run = FreeRunModel(model, data);
    benchmark::DoNotOptimize(run.simulated.rows());
  }
  state.counters["rk4_steps_per_second"] =
      benchmark::Counter(600.0 / 0.01 * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

BENCHMARK(BM_EquationModelFreeRun600s)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace usvid
