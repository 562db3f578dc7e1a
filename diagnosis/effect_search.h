// What is fitted for each effect of the catalogue: the free sizes, their public names, bounds
// and starting values, and how they set EffectValues<T>. Smooth effects (current, actuator lag,
// biases, inertia, damping, surge force, resistance, wind) are fitted by Ceres through the
// differentiable rollout; input delay and saturation move signals in time or clip them, so they are
// found by a bounded NLopt search.
//   effect        sizes                         bounds
//   input_delay   delay_s                       [0, 3] s
//   current       current_north, current_east   +-3 m/s each
//   actuator_lag  time_constant_s               [max(0.02 s, integration step), 30 s]
//   input_bias    bias (yaw input units)        +-peak |yaw command|
//   sensor_bias   bias [rad/s]                  +-(peak |measured rate| + 0.1)
//   inertia       scale                         [0.2, 5]
//   damping       scale                         [0.2, 5]
//   saturation    fraction                      [0.05, 1]
//   surge_force   acceleration [m/s^2]          +-0.5
//   resistance    scale                         [0.2, 5]
//   wind          scale                         [-2, 4], from 0 (vessels with a wind model,
//                                               records with wind channels)
#pragma once

#include <string>
#include <vector>

#include "diagnosis/measured_data.h"
#include "effects/effect.h"
#include "effects/effect_values.h"
#include "simulators/scalar.h"

namespace usvid::diagnosis {

struct EffectSearch {
  EffectKind kind;
  int input = -1;      // the one input it acts on (OnInputs kinds); -1: the kind's default
  bool smooth = true;  // Ceres (true) or NLopt (false)
  std::vector<std::string> names;
  std::vector<double> start, lower, upper;
  std::shared_ptr<const ResolvedTerm> term;  // missing_term: resolved against the vessel
  int size() const { return static_cast<int>(names.size()); }
};

// A missing term (kind missing_term, state and term set) as a search of its coefficient, from
// `effect`'s coefficient (the residual search's), within +-(10 |start| + 1e-6).
EffectSearch SearchForTerm(const Effect& effect, const std::vector<std::string>& state_names,
                           const std::vector<std::string>& input_names);

// `input` >= 0: the effect on that input alone (OnInputs kinds only).
EffectSearch SearchFor(EffectKind kind, const MeasuredData& data, int yaw_input, int input = -1);

// The sizes theta (the search's names order) into effect values, on the search's input alone
// when it has one; others stay as they are.
template <typename T>
void ApplySizes(const EffectSearch& search, const T* theta, EffectValues<T>& e) {
  const int input = search.input;
  switch (search.kind) {
    case EffectKind::kInputDelay:
      if (input < 0) {
        e.delay_s = ValueOf(theta[0]);
      } else {
        if (static_cast<int>(e.input_delays_s.size()) <= input)
          e.input_delays_s.resize(input + 1, 0.0);
        e.input_delays_s[input] = ValueOf(theta[0]);
      }
      break;
    case EffectKind::kCurrent:
      e.current_north = theta[0];
      e.current_east = theta[1];
      break;
    case EffectKind::kActuatorLag:
      e.lag_time_constant_s = theta[0];
      e.lag_inputs = input < 0 ? ~0u : 1u << input;
      break;
    case EffectKind::kInputBias:
      e.input_bias = theta[0];
      e.bias_input = input;
      break;
    case EffectKind::kSensorBias:
      e.sensor_bias = theta[0];
      break;
    case EffectKind::kInertia:
      e.inertia_scale = theta[0];
      break;
    case EffectKind::kDamping:
      e.damping_scale = theta[0];
      break;
    case EffectKind::kSaturation:
      e.saturation_fraction = ValueOf(theta[0]);
      e.saturation_inputs = input < 0 ? ~0u : 1u << input;
      break;
    case EffectKind::kSurgeForce:
      e.surge_acceleration = theta[0];
      break;
    case EffectKind::kResistance:
      e.resistance_scale = theta[0];
      break;
    case EffectKind::kWind:
      e.wind_scale = theta[0];
      break;
    case EffectKind::kMissingTerm:
      e.extra_terms.push_back({search.term, theta[0]});
      break;
  }
}

// The public names of the sizes (docs/data.md#effects).
std::vector<std::string> SizeNames(EffectKind kind);

// The effect of a search's sizes; a one-input search names its input from `input_names`.
Effect EffectOf(const EffectSearch& search, const std::vector<double>& theta,
                const std::vector<std::string>& input_names);

}  // namespace usvid::diagnosis
