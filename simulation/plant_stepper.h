// One integration step of a vessel with effects under a held input, by fixed-step RK4 or by
// adaptive Dormand-Prince over the same span. Shared by the open- and closed-loop runners.
#pragma once

#include <array>
#include <stdexcept>

#include "effects/plant.h"
#include "simulation/integrator.h"
#include "simulators/dormand_prince.h"
#include "simulators/rk4.h"

namespace usvid {

// The integrators a stepper can run: kAny (RK4 or adaptive Dormand-Prince, as `usvid simulate
// --integrator` offers), or kRk4Only for the fits, which differentiate fixed RK4 steps: not
// instantiating the adaptive integrator for their Jets takes a fifth off their compile time
// (docs/performance.md#build-time).
enum class Steppers { kAny, kRk4Only };

template <Vessel V, typename T, Steppers S = Steppers::kAny>
struct PlantStepper {
  using State = StateVector<T, Plant<V>::kStates>;

  const T* params_eff;  // after Plant<V>::ScaleParams
  const EffectValues<T>* effects;
  std::array<double, V::kInputs> limits;
  Integrator integrator = Integrator::kRk4;
  AdaptiveOptions adaptive;

  // Advances x by h with the commanded input u held; false if the adaptive step failed.
  bool Step(const T* u, double h, State& x) const {
    auto f = [&](const T* xs, T* dx) {
      Plant<V>::template Derivative<T>(xs, u, params_eff, *effects, limits, dx);
    };
    if (integrator == Integrator::kRk4) {
      Rk4Step<T, Plant<V>::kStates>(f, h, x);
      return true;
    }
    if constexpr (S == Steppers::kAny) {
      AdaptiveOptions opt = adaptive;
      opt.initial_step = std::min(opt.initial_step, h);
      return DormandPrinceIntegrate<T, Plant<V>::kStates>(f, h, x, opt).ok;
    } else {
      throw std::invalid_argument("PlantStepper: this rollout integrates by RK4 only");
    }
  }
};

// Total input delay: the vessel's own transport delay (if it has one) plus the effect's.
template <Vessel V>
double TotalDelay(double effect_delay_s) {
  if constexpr (requires { V::kTransportDelay; }) {
    return V::kTransportDelay + effect_delay_s;
  } else {
    return effect_delay_s;
  }
}

}  // namespace usvid
