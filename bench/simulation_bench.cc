// Whole simulations as `usvid simulate` runs them: 600 s of a maneuver at 20 Hz output with
// 0.01 s RK4 steps, the effects wrapper and the controller included (issue 3: well under 1 s).
#include <benchmark/benchmark.h>

#include "maneuvers/maneuver_factory.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

void BM_Simulate600s(benchmark::State& state, const std::string& vessel, const std::string& spec) {
  const VesselSimulator& sim = FindVessel(vessel);
  long steps = 0;
  for (auto _ : state) {
    auto m = MakeManeuver(spec, sim.Info().actuation, 600.0, 1);
    const SimulationResult r = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{});
    benchmark::DoNotOptimize(r.data.rows());
    steps += static_cast<long>((600.0 + r.run_in_s) / 0.01);
  }
  state.counters["rk4_steps_per_second"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}

BENCHMARK_CAPTURE(BM_Simulate600s, odin3dof_zigzag, std::string("odin3dof"),
                  std::string("zigzag:20/20"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Simulate600s, odin3dof_random, std::string("odin3dof"),
                  std::string("random-steps"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Simulate600s, eb2dof_multisine, std::string("eb2dof"),
                  std::string("multisine"))
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace usvid
