// usvid refit speed: multiple shooting through whole segments of an MMG model (kvlcc2, 66
// parameters), with R_0, Y_v, Y_r, N_v, N_r free (the vessel's refit set, as the KVLCC2 and Esso
// Osaka studies free five to twelve), and the same segments scored with the model held (a
// hybrid's held-out score, run once per proposal). Ceres differentiates by every value of the
// parameter block, so the free parameters get a block of their own (typed_refit.h); the
// whole vector was 2.7 times slower on the Esso Osaka runs (docs/performance.md, item 4).
#include <benchmark/benchmark.h>

#include "maneuvers/maneuver_factory.h"
#include "methods/refit/refit.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

// 600 s of kvlcc2 random rudder steps, 0.5 % noise, its hull's R_0 and N_r 20 % off the start.
struct RefitCase {
  Dataset data;
  std::vector<double> start;
};

const RefitCase& Kvlcc2Case() {
  static const RefitCase c = [] {
    const VesselSimulator& sim = FindVessel("kvlcc2");
    const VesselInfo& info = sim.Info();
    auto m = MakeManeuver("random-steps", info.actuation, 600.0, 11);
    Dataset d = sim.RunManeuver(*m, info.default_params, EffectValues<double>{}, RunOptions{}).data;
    AddGaussianNoise(d, info.states, 0.005, 11);
    std::vector<double> start = info.default_params;
    for (const char* name : {"R_0", "N_r"})
      start[std::find(info.params.begin(), info.params.end(), name) - info.params.begin()] *= 1.2;
    return RefitCase{std::move(d), std::move(start)};
  }();
  return c;
}

void BM_RefitKvlcc2(benchmark::State& state) {
  RefitOptions o;
  o.hold_model = state.range(0) == 1;
  RefitResult r;
  for (auto _ : state) r = RefitVessel("kvlcc2", Kvlcc2Case().data, Kvlcc2Case().start, o);
  state.counters["rows"] = static_cast<double>(Kvlcc2Case().data.rows());
  state.counters["iterations"] = r.iterations;
}
// Arg 0: the five fitted; 1: the model held, each segment's initial state fitted.
BENCHMARK(BM_RefitKvlcc2)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace usvid
