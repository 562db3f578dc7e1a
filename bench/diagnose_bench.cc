// usvid diagnose speed (issue 8: under a minute for 900 s at 20 Hz): the whole diagnosis of
// odin3dof random-step data with a hidden inertia error (all 8 effects fitted, initial states
// of every 10 s segment estimated, held-out scoring, residual analysis) at 1 and 2 threads.
#include <benchmark/benchmark.h>
#include <omp.h>

#include "diagnosis/diagnose.h"
#include "maneuvers/maneuver_factory.h"
#include "sensors/noise.h"

namespace usvid {
namespace {

const Dataset& Data900s() {
  static const Dataset data = [] {
    const VesselSimulator& sim = FindVessel("odin3dof");
    auto m = MakeManeuver("random-steps", sim.Info().actuation, 900.0, 5);
    EffectValues<double> e;
    e.inertia_scale = 1.6;
    Dataset d = sim.RunManeuver(*m, sim.Info().default_params, e, RunOptions{}).data;
    AddGaussianNoise(d, sim.Info().states, 0.005, 5);
    return d;
  }();
  return data;
}

void BM_Diagnose900s(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const auto& params = FindVessel("odin3dof").Info().default_params;
  diagnosis::Diagnosis d;
  for (auto _ : state) d = diagnosis::Diagnose(Data900s(), "odin3dof", params, {});
  state.counters["rows"] = static_cast<double>(Data900s().rows());
  state.counters["found_inertia"] = d.cause == "inertia";
}
BENCHMARK(BM_Diagnose900s)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace usvid
