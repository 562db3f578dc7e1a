// Classical fixed-step Runge-Kutta 4 for x' = f(x), any scalar T (double, ceres::Jet):
//   k1 = f(x), k2 = f(x + h/2 k1), k3 = f(x + h/2 k2), k4 = f(x + h k3),
//   x += h/6 (k1 + 2 k2 + 2 k3 + k4).
// The inputs are held constant over the step by the caller (zero-order hold), so f sees one
// input vector for all four stages. No allocation: the state is a fixed-size Eigen vector.
#pragma once

#include <Eigen/Core>

// Under AddressSanitizer the flattened Jet steps of several vessels in one file take GCC tens of
// minutes to compile, and speed is not what a sanitizer build is for: there the step is a plain
// function.
#if defined(__SANITIZE_ADDRESS__)
#define USVID_FLATTEN
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define USVID_FLATTEN
#endif
#endif
#ifndef USVID_FLATTEN
#define USVID_FLATTEN [[gnu::flatten]]
#endif

namespace usvid {

template <typename T, int N>
using StateVector = Eigen::Matrix<T, N, 1>;

// How a step calls f (docs/performance.md#build-time). Everything f calls is inlined into it
// (flatten): with ceres::Jet the arithmetic is hundreds of small inline operators, and GCC stops
// inlining them once a translation unit grows (several vessels instantiated in one file made the
// Jet step 3x slower). For a Jet of 5 derivatives or more each of the four stages is one such
// flattened function, called four times: four inlined copies of a vessel's Jet derivative in one
// step took GCC 3.6 times as long to compile (62 s against 17 s for the five vessels' Jet
// benchmark), and the step runs as many instructions. The bound was 8 until the effect fitters'
// one-size Jets (a vessel's states and one effect size, 7 for mmg) showed the same: the mmg
// effect fitter compiled in 13 s instead of 23 s, and the diagnosis ran no slower. For double
// and the smallest Jets (msd's) the whole step is flattened, as there a call per stage costs as
// much as the stage (msd: 46 ns a step).
template <typename T>
concept WideJet = requires {
  T::DIMENSION;
}
&&T::DIMENSION >= 5;

template <typename T, typename F>
[[gnu::noinline]] USVID_FLATTEN void Rk4Stage(const F& f, const T* x, T* dx) {
  f(x, dx);
}

template <typename T, typename F>
inline void Rk4Evaluate(const F& f, const T* x, T* dx) {
  if constexpr (WideJet<T>)
    Rk4Stage(f, x, dx);
  else
    f(x, dx);
}

template <typename T, int N, typename F>
USVID_FLATTEN void Rk4Step(const F& f, double h, StateVector<T, N>& x) {
  StateVector<T, N> k1, k2, k3, k4, y;
  Rk4Evaluate(f, x.data(), k1.data());
  y = x + (0.5 * h) * k1;
  Rk4Evaluate(f, y.data(), k2.data());
  y = x + (0.5 * h) * k2;
  Rk4Evaluate(f, y.data(), k3.data());
  y = x + h * k3;
  Rk4Evaluate(f, y.data(), k4.data());
  x += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

}  // namespace usvid
