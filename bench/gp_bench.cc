// GP-SR speed (issue 5 and 10), on the shared fixture (bench/fixtures.h):
//  - the batch interpreter's node evaluations per second, float and double, 1 and 2 threads
//    (goal: Operon's 3e9 to 6e9 per core in float with AVX2);
//  - evaluation cost against the number of rows, 1k to 100k (it should grow linearly);
//  - the GP-OLS scoring of one individual: the report's ERR threshold, and the default
//    held-out term selection over contiguous blocks;
//  - the constant optimisation of one elite (Levenberg-Marquardt, 5 iterations, 4000 rows);
//  - one generation at population 2000 (with the initial population it is bred from);
//  - the peak heap a search of population 2000 x 10 generations needs;
//  - a full search of population 2000 x 50 generations on 10k rows (r', + - * abs), at 1 and
//    2 threads: the OpenMP speed-up.
#include <benchmark/benchmark.h>

#include "bench/fixtures.h"
#include "bench/heap_counter.h"
#include "methods/gp/constant_fit.h"
#include "methods/gp/interpreter.h"
#include "methods/gp/search.h"

namespace usvid::gp {
namespace {

using bench::OdinGpProblem;
using bench::RandomTrees;

// Evaluates every random tree over `rows` rows of 6 variables; returns node evaluations.
template <typename T>
double EvaluateAll(Interpreter<T>& interp, long rows) {
  double nodes = 0.0;
  for (const Tree& tree : RandomTrees()) {
    for (long begin = 0; begin < rows; begin += Interpreter<T>::kBatch) {
      const int count = static_cast<int>(std::min<long>(Interpreter<T>::kBatch, rows - begin));
      interp.Evaluate(tree, begin, count);
      benchmark::DoNotOptimize(interp.Column(static_cast<int>(tree.size()) - 1));
    }
    nodes += static_cast<double>(tree.size()) * static_cast<double>(rows);
  }
  return nodes;
}

template <typename T>
std::vector<std::vector<T>> Columns(long rows) {
  std::vector<std::vector<T>> data(6, std::vector<T>(rows));
  for (int v = 0; v < 6; ++v)
    for (long r = 0; r < rows; ++r) data[v][r] = static_cast<T>(std::sin(0.001 * r * (v + 1)));
  return data;
}

template <typename T>
void BM_NodeEvaluations(benchmark::State& state) {
  const long rows = state.range(0);
  const auto data = Columns<T>(rows);
  std::vector<const T*> columns;
  for (const auto& d : data) columns.push_back(d.data());
  Interpreter<T> interp(columns);
  double nodes = 0.0;
  for (auto _ : state) nodes += EvaluateAll(interp, rows);
  state.counters["node_evals_per_second"] = benchmark::Counter(nodes, benchmark::Counter::kIsRate);
  state.SetComplexityN(rows);
}
BENCHMARK(BM_NodeEvaluations<float>)
    ->Arg(10000)
    ->Threads(1)
    ->Threads(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NodeEvaluations<double>)
    ->Arg(10000)
    ->Threads(1)
    ->Threads(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
// Cost against rows: linear (Google Benchmark fits O(N) and reports the RMS of the fit).
BENCHMARK(BM_NodeEvaluations<float>)
    ->Name("BM_NodeEvaluationsRows<float>")
    ->RangeMultiplier(10)
    ->Range(1000, 100000)
    ->Arg(30000)
    ->Complexity(benchmark::oN)
    ->Unit(benchmark::kMillisecond);

// GP-OLS scoring of one individual on all 10k rows (double): evaluation, Gram, ERR, refit.
void BM_OlsScore(benchmark::State& state) {
  const GpProblem& p = OdinGpProblem();
  size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        FitTree(RandomTrees()[i++ % RandomTrees().size()], p, ReportOptions()));
}
BENCHMARK(BM_OlsScore)->Unit(benchmark::kMicrosecond);

// The same with the default term selection: held-out error over contiguous blocks.
void BM_OlsHeldOutScore(benchmark::State& state) {
  const GpProblem& p = OdinGpProblem();
  const GpOptions options;
  size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(FitTree(RandomTrees()[i++ % RandomTrees().size()], p, options));
}
BENCHMARK(BM_OlsHeldOutScore)->Unit(benchmark::kMicrosecond);

// Constant optimisation of one elite as the search does it: r' = b + w1 abs(r - c) r + w2 v +
// w3 tau_n on 4000 rows, c starting at 0.1 (truth: 0), 5 Levenberg-Marquardt iterations.
void BM_ConstantFit(benchmark::State& state) {
  const GpProblem& p = OdinGpProblem();
  const long rows = std::min<long>(4000, p.target.size());
  Model m;
  m.tree = {{Op::kVar, 2, 1, 0.0}, {Op::kConst, 0, 1, 0.1}, {Op::kSub, 0, 1, 0.0},
            {Op::kAbs, 0, 1, 0.0}, {Op::kVar, 2, 1, 0.0},   {Op::kMul, 0, 1, 0.0},
            {Op::kVar, 1, 1, 0.0}, {Op::kAdd, 0, 1, 0.0},   {Op::kVar, 5, 1, 0.0},
            {Op::kAdd, 0, 1, 0.0}};
  UpdateLengths(m.tree);
  m.term_roots = {5, 6, 8};
  m.weights = {-0.1, -0.06, 4.7e-5};
  std::vector<const double*> columns;
  for (const Eigen::VectorXd& v : p.variables) columns.push_back(v.data());
  ConstantFitResult r;
  for (auto _ : state) r = FitConstants(m, columns, p.target.data(), rows, 5);
  state.counters["c"] = r.tree[1].value;
  state.counters["iterations"] = r.iterations;
  state.counters["rows"] = static_cast<double>(rows);
}
BENCHMARK(BM_ConstantFit)->Unit(benchmark::kMillisecond);

GpOptions SearchOptions(int generations, int threads) {
  GpOptions opt;
  opt.functions = {Op::kAdd, Op::kSub, Op::kMul, Op::kAbs};
  opt.generations = generations;
  opt.stagnation = 1000;  // no early stop
  opt.fit_rows = 0;       // every row
  opt.threads = threads;
  return opt;
}

// One generation at population 2000: the initial population and one bred from it, 10k rows.
void BM_OneGeneration(benchmark::State& state) {
  GpResult r;
  for (auto _ : state) r = RunGp(OdinGpProblem(), SearchOptions(1, 1));
  state.counters["node_evals_per_second"] = r.node_evaluations / r.seconds;
}
BENCHMARK(BM_OneGeneration)->Iterations(3)->UseRealTime()->Unit(benchmark::kMillisecond);

// The heap a search needs at its peak, above what the process held before (MB).
void BM_GpPeakHeap(benchmark::State& state) {
  const GpProblem& p = OdinGpProblem();
  double peak_mb = 0.0;
  for (auto _ : state) {
    const std::size_t before = bench::HeapInUse();
    bench::ResetHeapPeak();
    benchmark::DoNotOptimize(RunGp(p, SearchOptions(10, static_cast<int>(state.range(0)))));
    peak_mb = static_cast<double>(bench::HeapPeak() - before) / 1e6;
  }
  state.counters["peak_heap_MB"] = peak_mb;
}
BENCHMARK(BM_GpPeakHeap)->Arg(1)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

// The full search the issue times: population 2000, 50 generations (no early stop), 10k rows.
void BM_FullSearch(benchmark::State& state) {
  GpResult r;
  for (auto _ : state)
    r = RunGp(OdinGpProblem(), SearchOptions(50, static_cast<int>(state.range(0))));
  state.counters["node_evals_per_second"] = r.node_evaluations / r.seconds;
  state.counters["r2"] = r.best.r2;
}
BENCHMARK(BM_FullSearch)->Arg(1)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace
}  // namespace usvid::gp
