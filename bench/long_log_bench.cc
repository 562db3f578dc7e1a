// Peak heap per stage on a long log (issue 25, docs/performance.md#long-logs): a 1-hour odin3dof
// random-step log at 50 Hz (180001 rows x 10 columns, 14.4 MB as doubles), written as CSV once,
// then each stage's peak heap above what the process held before it, in MB and as a multiple of
// the data as doubles: reading the CSV, preprocessing, identify with sindy, gp and fossen-ceres,
// and diagnose. The acceptance's ratios are of peak RSS, measured by tools/long-log-study.sh;
// these isolate each stage's own share, to guard it against regressions.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <filesystem>

#include "bench/heap_counter.h"
#include "core/csv_dataset.h"
#include "diagnosis/diagnose.h"
#include "maneuvers/maneuver_factory.h"
#include "methods/fossen_ceres/fossen_fit.h"
#include "methods/gp/gp_identify.h"
#include "methods/identify.h"
#include "methods/sindy/sindy.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

// The log's CSV, in the temporary folder (removed at exit).
const std::string& LongLogFile() {
  static const struct File {
    std::string path = (std::filesystem::temp_directory_path() / "usvid_long_log_bench.csv").string();
    File() {
      const VesselSimulator& sim = FindVessel("odin3dof");
      auto m = MakeManeuver("random-steps", sim.Info().actuation, 3600.0, 1);
      RunOptions run;
      run.rate_hz = 50.0;
      Dataset d = sim.RunManeuver(*m, sim.Info().default_params, {}, run).data;
      AddGaussianNoise(d, sim.Info().states, 0.005, 1);
      WriteDatasetCsv(path, d);
    }
    ~File() { std::filesystem::remove(path); }
  } file;
  return file.path;
}

const Dataset& LongLog() {
  static const Dataset data = ReadDatasetCsv(LongLogFile());
  return data;
}

double AsDoublesMb(const Dataset& d) {
  return static_cast<double>(d.rows() * (1 + static_cast<Eigen::Index>(d.channels().size()))) *
         8.0 / 1e6;
}

// Runs `stage` once, reporting its peak heap above what was held before it.
template <typename Stage>
void PeakHeap(benchmark::State& state, Stage stage) {
  const double data_mb = AsDoublesMb(LongLog());
  omp_set_num_threads(2);
  double peak_mb = 0.0;
  for (auto _ : state) {
    const std::size_t before = bench::HeapInUse();
    bench::ResetHeapPeak();
    stage();
    peak_mb = static_cast<double>(bench::HeapPeak() - before) / 1e6;
  }
  state.counters["rows"] = static_cast<double>(LongLog().rows());
  state.counters["peak_heap_MB"] = peak_mb;
  state.counters["x_data"] = peak_mb / data_mb;
}

void BM_LongLogRead(benchmark::State& state) {
  PeakHeap(state, [] { benchmark::DoNotOptimize(ReadDatasetCsv(LongLogFile())); });
}
BENCHMARK(BM_LongLogRead)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

void BM_LongLogPreprocess(benchmark::State& state) {
  PeakHeap(state, [] {
    benchmark::DoNotOptimize(
        Preprocess(LongLog(), {"u", "v", "r"}, {"tau_x", "tau_y", "tau_n"}, PreprocessOptions{}));
  });
}
BENCHMARK(BM_LongLogPreprocess)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

// identify with `method`: the data copied in, as the command moves its own in (the copy is the
// data, counted once, as the command's read is).
void LongLogIdentify(benchmark::State& state, std::string_view method) {
  IdentifyRequest request;
  request.method = std::string(method);
  request.vessel = "odin3dof";
  request.threads = 2;
  PeakHeap(state, [&] { benchmark::DoNotOptimize(Identify(LongLog(), request)); });
}
void BM_LongLogSindy(benchmark::State& state) { LongLogIdentify(state, sindy::kMethodName); }
void BM_LongLogGp(benchmark::State& state) { LongLogIdentify(state, gp::kMethodName); }
void BM_LongLogFossen(benchmark::State& state) { LongLogIdentify(state, fossen::kMethodName); }
BENCHMARK(BM_LongLogSindy)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK(BM_LongLogGp)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK(BM_LongLogFossen)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

void BM_LongLogDiagnose(benchmark::State& state) {
  const auto& params = FindVessel("odin3dof").Info().default_params;
  PeakHeap(state, [&] {
    benchmark::DoNotOptimize(diagnosis::Diagnose(LongLog(), "odin3dof", params, {}));
  });
}
BENCHMARK(BM_LongLogDiagnose)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace
}  // namespace usvid
