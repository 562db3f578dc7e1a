// GP-SR speed (issue 5 and 10): the batch interpreter's node evaluations per second in float and
// double at 1 and 2 threads (goal: Operon's 3e9 to 6e9 per core in float with AVX2), the
// GP-OLS scoring of one individual, and a full search of population 2000 x 50 generations on
// 10k rows of odin3dof data (r', operators +,-,*,abs).
#include <benchmark/benchmark.h>

#include "maneuvers/maneuver_factory.h"
#include "methods/gp/interpreter.h"
#include "methods/gp/search.h"
#include "methods/gp/variation.h"
#include "preprocessing/pipeline.h"
#include "simulation/vessel_simulator.h"

namespace usvid::gp {
namespace {

constexpr long kRows = 10000;

const std::vector<Tree>& Trees() {
  static const std::vector<Tree> trees = [] {
    PrimitiveSet set{{Op::kAdd, Op::kSub, Op::kMul, Op::kAbs}, 6, 0.1};
    std::vector<Tree> t;
    for (int i = 0; i < 200; ++i) {
      Rng rng = StreamFor(7, 0, static_cast<uint64_t>(i));
      t.push_back(RandomTree(rng, set, 6, i % 2 == 0));
    }
    return t;
  }();
  return trees;
}

template <typename T>
void BM_NodeEvaluations(benchmark::State& state) {
  std::vector<std::vector<T>> data(6, std::vector<T>(kRows));
  for (int v = 0; v < 6; ++v)
    for (long r = 0; r < kRows; ++r) data[v][r] = static_cast<T>(std::sin(0.001 * r * (v + 1)));
  std::vector<const T*> columns;
  for (const auto& d : data) columns.push_back(d.data());
  Interpreter<T> interp(columns);
  double nodes = 0.0;
  for (auto _ : state) {
    for (const Tree& tree : Trees()) {
      for (long begin = 0; begin < kRows; begin += Interpreter<T>::kBatch) {
        const int count = static_cast<int>(std::min<long>(Interpreter<T>::kBatch, kRows - begin));
        interp.Evaluate(tree, begin, count);
        benchmark::DoNotOptimize(interp.Column(static_cast<int>(tree.size()) - 1));
      }
      nodes += static_cast<double>(tree.size()) * kRows;
    }
  }
  state.counters["node_evals_per_second"] = benchmark::Counter(nodes, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_NodeEvaluations<float>)
    ->Threads(1)
    ->Threads(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NodeEvaluations<double>)
    ->Threads(1)
    ->Threads(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

const GpProblem& OdinProblem() {
  static const GpProblem problem = [] {
    const VesselSimulator& sim = FindVessel("odin3dof");
    auto m = MakeManeuver("random-steps", sim.Info().actuation, kRows / 20.0, 5);
    const Dataset d = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
    const PreparedData prep = Preprocess(d, {"u", "v", "r"}, {"tau_x", "tau_y", "tau_n"}, {});
    GpProblem p;
    p.names = {"u", "v", "r", "tau_x", "tau_y", "tau_n"};
    for (const std::string& n : p.names) p.variables.push_back(prep.data[n]);
    p.target = prep.data["r_dot"];
    return p;
  }();
  return problem;
}

// GP-OLS scoring of one individual on all 10k rows (double): evaluation, Gram, ERR, refit.
void BM_OlsScore(benchmark::State& state) {
  const GpProblem& p = OdinProblem();
  size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(FitTree(Trees()[i++ % Trees().size()], p, 0.05));
}
BENCHMARK(BM_OlsScore)->Unit(benchmark::kMicrosecond);

// The full search the issue times: population 2000, 50 generations (no early stop), 10k rows.
void BM_FullSearch(benchmark::State& state) {
  GpOptions opt;
  opt.functions = {Op::kAdd, Op::kSub, Op::kMul, Op::kAbs};
  opt.stagnation = 1000;
  opt.fit_rows = 0;  // every row
  opt.threads = static_cast<int>(state.range(0));
  GpResult r;
  for (auto _ : state) r = RunGp(OdinProblem(), opt);
  state.counters["node_evals_per_second"] = r.node_evaluations / r.seconds;
  state.counters["r2"] = r.best.r2;
}
BENCHMARK(BM_FullSearch)->Arg(1)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace
}  // namespace usvid::gp
