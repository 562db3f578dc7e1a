// The benchmark itself as `usvid compare --quick` runs it (issue 10): the embedded quick suite
// (two vessels, three training maneuvers, four methods), fits in parallel with OpenMP, at 1 and
// 2 threads: the wall time and the speed-up (goal: at least 1.8x on 2 cores). The default suite
// (goal: under 10 minutes on 2 cores) is timed by `time usvid compare` in docs/performance.md.
#include <benchmark/benchmark.h>

#include "harness/embedded_suites.h"
#include "harness/run_suite.h"
#include "harness/suite.h"

namespace usvid {
namespace {

void BM_CompareQuick(benchmark::State& state) {
  const Suite suite = LoadEmbeddedSuite("quick");
  size_t rows = 0;
  for (auto _ : state) rows = RunSuite(suite, static_cast<int>(state.range(0))).size();
  state.counters["rows"] = static_cast<double>(rows);
}
BENCHMARK(BM_CompareQuick)->Arg(1)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace
}  // namespace usvid
