// Open-loop rollout of a vessel with effects, driven by recorded commands (zero-order hold),
// for any scalar T: with T = ceres::Jet the whole rollout is differentiated with respect to the
// parameters, the effect values and the initial state. Between consecutive output times the
// span is split into equal substeps of at most max_step; the input of each substep is the
// command in force at (substep start - delay).
#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

#include "simulation/input_track.h"
#include "simulation/plant_stepper.h"

namespace usvid {

struct OpenLoopSetup {
  const InputTrack* inputs = nullptr;
  std::vector<double> times;  // output times, increasing; times[0] is the initial state's
  double max_step = 0.01;
  Integrator integrator = Integrator::kRk4;
  // Rows whose |value| exceeds this count as diverged (the run stops there).
  double divergence_bound = 1e7;
};

// out: times.size() rows of Plant<V>::kStates values (row-major), filled up to the row where
// the run diverged; returns the number of rows filled (== times.size() unless it diverged).
// S = Steppers::kRk4Only: setup.integrator must be RK4 (plant_stepper.h; the fits' rollouts).
template <Vessel V, typename T, Steppers S = Steppers::kAny>
size_t RolloutOpenLoop(const OpenLoopSetup& setup, const T* x0, const T* params,
                       const EffectValues<T>& effects, const std::array<double, V::kInputs>& limits,
                       T* out) {
  constexpr int N = Plant<V>::kStates;
  if (!(setup.max_step > 0.0)) throw std::invalid_argument("RolloutOpenLoop: max_step must be > 0");
  std::array<T, V::kParams> p_eff;
  Plant<V>::ScaleParams(params, effects, p_eff.data());
  PlantStepper<V, T, S> stepper{p_eff.data(), &effects, limits, setup.integrator, {}};
  const double delay = TotalDelay<V>(effects.delay_s);
  typename PlantStepper<V, T>::State x;
  for (int i = 0; i < N; ++i) x(i) = x0[i];
  std::array<T, V::kInputs> u;
  InputTrack::Cursor cursor;
  for (size_t k = 0; k < setup.times.size(); ++k) {
    if (k > 0) {
      const double span = setup.times[k] - setup.times[k - 1];
      const int n = std::max(1, static_cast<int>(std::ceil(span / setup.max_step - 1e-9)));
      const double h = span / n;
      for (int s = 0; s < n; ++s) {
        setup.inputs->Delayed(setup.times[k - 1] + s * h, delay, effects.input_delays_s, u.data(),
                              cursor);
        if (!stepper.Step(u.data(), h, x)) return k;
      }
    }
    for (int i = 0; i < N; ++i) {
      const double value = ValueOf(x(i));
      if (!std::isfinite(value) || std::abs(value) > setup.divergence_bound) return k;
      out[k * N + i] = x(i);
    }
  }
  return setup.times.size();
}

}  // namespace usvid
