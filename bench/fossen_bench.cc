// Ceres fits (issue 6 and 10), on the shared fixture (bench/fixtures.h), one core:
//  - fossen-ceres' equation-error fit of odin3dof's 10 parameters on 18k samples, and its cost
//    against the number of samples (1k to 100k: linear);
//  - the multiple-shooting fit of the same 10 parameters (plus 3 initial velocities per 10 s
//    segment) from the equation-error start;
//  - the 12-parameter multiple-shooting fit (the waterjet model's 13 with m11 held) on 18k
//    samples (goal: under 1 s): on data of that model (its error then is the noise), and on
//    odin-hs, which it cannot match (Ceres runs to its 100-iteration cap: the cost of a misfit);
//  - the shooting fit the default compare runs on odin-hs: JetForceModel's 60 parameters on the
//    jets' forces, 300 s of random steps at 10 Hz (its derivatives taken over a window of its
//    resistance knots, methods/fossen_ceres/knot_window_cost.h).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "bench/fixtures.h"
#include "methods/fossen_ceres/fossen_fit.h"
#include "methods/fossen_ceres/fossen_models.h"
#include "methods/fossen_ceres/jet_force_model.h"

namespace usvid {
namespace {

using bench::OdinHsPrepared;
using bench::OdinPrepared;

void BM_FossenEquationError(benchmark::State& state) {
  const PreparedData& data = OdinPrepared(state.range(0));
  fossen::FossenFit fit;
  for (auto _ : state) fit = fossen::FitEquationErrorFor<fossen::Odin3DofModel>(data, {});
  state.counters["samples"] = static_cast<double>(data.data.rows());
  state.counters["iterations"] = fit.iterations;  // the cost per iteration is what grows with N
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_FossenEquationError)->Arg(18000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FossenEquationError)
    ->Name("BM_FossenEquationErrorRows")
    ->RangeMultiplier(10)
    ->Range(1000, 100000)
    ->Arg(30000)
    ->Complexity(benchmark::oN)
    ->Unit(benchmark::kMillisecond);

void BM_FossenMultipleShooting(benchmark::State& state) {
  const auto start = fossen::FitEquationErrorFor<fossen::Odin3DofModel>(OdinPrepared(), {}).params;
  fossen::FossenFit fit;
  for (auto _ : state)
    fit = fossen::FitSimulationErrorFor<fossen::Odin3DofModel>(OdinPrepared(), start, {});
  state.counters["samples"] = static_cast<double>(OdinPrepared().data.rows());
  state.counters["iterations"] = fit.iterations;
}
BENCHMARK(BM_FossenMultipleShooting)->Unit(benchmark::kMillisecond);

void BM_Fossen12ParameterShooting(benchmark::State& state, const PreparedData& (*data)()) {
  const auto start = fossen::FitEquationErrorFor<fossen::WaterjetModel>(data(), {}).params;
  fossen::BasicFossenFit<13> fit;
  for (auto _ : state)
    fit = fossen::FitSimulationErrorFor<fossen::WaterjetModel>(data(), start, {});
  state.counters["samples"] = static_cast<double>(data().data.rows());
  state.counters["iterations"] = fit.iterations;
  double worst = 0.0;
  for (int i = 0; i < 13; ++i)
    worst = std::max(worst, std::abs(fit.params[i] / bench::WaterjetTruth()[i] - 1.0));
  state.counters["worst_parameter_error"] = worst;
}
BENCHMARK_CAPTURE(BM_Fossen12ParameterShooting, own_model, &bench::WaterjetModelPrepared)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Fossen12ParameterShooting, odin_hs_misfit, &OdinHsPrepared)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

void BM_FossenJetForceShooting(benchmark::State& state) {
  const PreparedData& data = bench::JetForcesPrepared();
  const auto start = fossen::FitEquationErrorFor<fossen::JetForceModel>(data, {}).params;
  fossen::BasicFossenFit<fossen::JetForceModel::kParams> fit;
  for (auto _ : state) fit = fossen::FitSimulationErrorFor<fossen::JetForceModel>(data, start, {});
  state.counters["samples"] = static_cast<double>(data.data.rows());
  state.counters["iterations"] = fit.iterations;
}
BENCHMARK(BM_FossenJetForceShooting)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace usvid
