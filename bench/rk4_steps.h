// RK4 steps per second of one vessel in scalar T (double, or ceres::Jet with derivatives with
// respect to all parameters), on one thread. The double benchmarks (simulators_bench.cc) and the
// Jet ones (simulators_jet_bench.cc) are compiled as the library's double and Jet code are.
#pragma once

#include <benchmark/benchmark.h>

#include <array>
#include <type_traits>

#include "simulators/rk4.h"
#include "simulators/vessel.h"

namespace usvid::bench {

template <typename V, typename T>
void BM_Rk4Steps(benchmark::State& state) {
  StateVector<T, V::kStates> x0 = StateVector<T, V::kStates>::Constant(T(0.1));
  if constexpr (V::kStates > 3) x0(3) = T(6.0);
  if constexpr (requires { V::kIdleRpm; }) x0(6) = T(1200.0), x0(8) = T(1.0);  // odin-hs jets
  StateVector<T, V::kStates> x;
  std::array<T, V::kInputs> u;
  for (int i = 0; i < V::kInputs; ++i) u[i] = T(0.3 * V::kInputMax[i]);
  std::array<T, V::kParams> p;
  for (int i = 0; i < V::kParams; ++i) {
    if constexpr (std::is_same_v<T, double>) {
      p[i] = V::kDefaultParams[i];
    } else {
      p[i] = T(V::kDefaultParams[i], i);
    }
  }
  const Environment<T> env;
  auto f = [&](const T* xs, T* dx) { V::template Derivative<T>(xs, u.data(), p.data(), env, dx); };
  for (auto _ : state) {
    x = x0;  // 1 s of motion per batch, from the same realistic state
    for (int k = 0; k < 1000; ++k) Rk4Step<T, V::kStates>(f, 1e-3, x);
    benchmark::DoNotOptimize(x);
  }
  state.counters["steps_per_second"] =
      benchmark::Counter(1000.0 * state.iterations(), benchmark::Counter::kIsRate);
}

}  // namespace usvid::bench
