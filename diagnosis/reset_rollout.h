// The rollout every diagnosis score comes from: vessel V with effects, driven by the recorded
// commands over one part of the data, its measured states reset at the start of every segment
// (measured_data.h). With T = ceres::Jet the residuals carry derivatives with respect to the
// effect sizes. Residual of channel c at row k:
//   e = (y_model(k) [+ sensor_bias if c is the gyro] - y_measured(k)) / scale_c,
// the heading error wrapped to (-pi, pi], 0 where the channel was not sampled. At a segment start
// the measured states are set to their smoothed values, the gyro's minus the sensor bias. A segment whose state leaves
// the divergence bound predicts zero until the next reset.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

#include "diagnosis/measured_data.h"
#include "simulation/plant_stepper.h"

namespace usvid::diagnosis {

// Residuals of a part: (part.end - part.begin) x channels values, row-major.
inline Eigen::Index ResidualCount(const MeasuredData& d, const Part& part) {
  return (part.end - part.begin) * static_cast<Eigen::Index>(d.channels.size());
}

template <Vessel V, typename T>
void ResetRollout(const MeasuredData& d, const Part& part, const std::array<double, V::kParams>& p,
                  const EffectValues<T>& e, T* residual) {
  constexpr int N = Plant<V>::kStates;
  constexpr double kBound = 1e7;
  std::array<T, V::kParams> p_nom, p_eff;
  for (int i = 0; i < V::kParams; ++i) p_nom[i] = T(p[i]);
  Plant<V>::ScaleParams(p_nom.data(), e, p_eff.data());
  std::array<double, V::kInputs> peak{};
  for (int i = 0; i < V::kInputs; ++i) peak[i] = d.peak_command[i];
  const auto limits = SaturationLimits<V::kInputs>(e.saturation_fraction, peak);
  PlantStepper<V, T> stepper{p_eff.data(), &e, limits, Integrator::kRk4, {}};
  const double delay = TotalDelay<V>(e.delay_s);
  const int channels = static_cast<int>(d.channels.size());

  typename PlantStepper<V, T>::State x;
  for (int i = 0; i < V::kStates; ++i) x(i) = T(d.fallback_states(part.begin, i));
  {
    std::array<T, V::kInputs> u0;
    d.inputs.Delayed(d.times[part.begin], delay, e.input_delays_s, u0.data());
    Plant<V>::InitialLagState(u0.data(), x.data());
  }
  size_t next_start = 0;
  bool diverged = false;
  std::array<T, V::kInputs> u;
  for (Eigen::Index k = part.begin; k < part.end; ++k) {
    if (next_start < part.starts.size() && part.starts[next_start] == k) {
      ++next_start;
      diverged = false;
      for (int i = 0; i < V::kStates; ++i) {
        const int c = d.state_channel[i];
        if (c >= 0 && d.sampled(k, c)) {
          x(i) = T(d.reset(k, c));
          if (c == d.rate_channel) x(i) -= e.sensor_bias;
        } else if (!std::isfinite(ValueOf(x(i)))) {
          x(i) = T(d.fallback_states(k, i));
        }
      }
    }
    T* res = residual + (k - part.begin) * channels;
    for (int c = 0; c < channels; ++c) {
      if (!d.sampled(k, c)) {
        res[c] = T(0);
        continue;
      }
      T model = diverged ? T(0) : x(d.channel_state[c]);
      if (c == d.rate_channel) model += e.sensor_bias;
      T diff = model - T(d.measured(k, c));
      if (c == d.heading_channel) {
        const double turns = std::round(ValueOf(diff) / (2.0 * std::numbers::pi));
        diff -= T(turns * 2.0 * std::numbers::pi);
      }
      res[c] = diff / d.scale[c];
    }
    if (k + 1 == part.end || diverged) continue;
    const double span = d.times[k + 1] - d.times[k];
    const int n = std::max(1, static_cast<int>(std::ceil(span / d.max_step - 1e-9)));
    const double h = span / n;
    for (int s = 0; s < n; ++s) {
      d.inputs.Delayed(d.times[k] + s * h, delay, e.input_delays_s, u.data());
      stepper.Step(u.data(), h, x);
    }
    for (int i = 0; i < N; ++i) {
      const double v = ValueOf(x(i));
      if (!std::isfinite(v) || std::abs(v) > kBound) diverged = true;
    }
  }
}

}  // namespace usvid::diagnosis
