// The rollouts every diagnosis score comes from: vessel V with effects, driven by the recorded
// commands over one part of the data (measured_data.h). With T = ceres::Jet the residuals carry
// derivatives with respect to the effect sizes and the segments' initial states. Residual of
// channel c at row k:
//   e = (y_model(k) [+ sensor_bias if c is the gyro] - y_measured(k)) / scale_c,
// the heading error wrapped to (-pi, pi], 0 where the channel was not sampled. A segment whose
// state leaves the divergence bound predicts zero to its end.
//  - ResetRollout: the whole part in one run, the measured states set to their smoothed values
//    at every segment start (the gyro's minus the sensor bias); actuator memory runs on.
//  - SegmentRollout: one segment from a given initial vessel state, the actuators' lag state
//    at its start filtered exactly from the part's start (segment_cost.h frees the initial
//    state, as MATLAB's compare does with 'InitialCondition', 'estimate').
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

// Vessel V with effect values e, ready to step.
template <Vessel V, typename T>
struct EffectPlant {
  std::array<T, V::kParams> p_eff;
  std::array<double, V::kInputs> limits;
  double delay;
  const EffectValues<T>* e;

  EffectPlant(const MeasuredData& d, const std::array<double, V::kParams>& p,
              const EffectValues<T>& effects)
      : delay(TotalDelay<V>(effects.delay_s)), e(&effects) {
    std::array<T, V::kParams> p_nom;
    for (int i = 0; i < V::kParams; ++i) p_nom[i] = T(p[i]);
    Plant<V>::ScaleParams(p_nom.data(), effects, p_eff.data());
    std::array<double, V::kInputs> peak{};
    for (int i = 0; i < V::kInputs; ++i) peak[i] = d.peak_command[i];
    limits =
        SaturationLimits<V::kInputs>(effects.saturation_fraction, peak, effects.saturation_inputs);
  }
  PlantStepper<V, T, Steppers::kRk4Only> Stepper() const {
    return {p_eff.data(), e, limits, Integrator::kRk4, {}};
  }
};

// Scores rows [a, b) of a part from plant state x at row a (x is advanced); residuals of row k
// go to residual[(k - part_begin) * channels]. Returns true if the run diverged.
template <Vessel V, typename T>
bool RolloutRows(const MeasuredData& d, Eigen::Index part_begin, Eigen::Index a, Eigen::Index b,
                 const EffectPlant<V, T>& plant, typename PlantStepper<V, T>::State& x,
                 T* residual) {
  constexpr int N = Plant<V>::kStates;
  constexpr double kBound = 1e7;
  const auto stepper = plant.Stepper();
  const int channels = static_cast<int>(d.channels.size());
  bool diverged = false;
  std::array<T, V::kInputs> u;
  InputTrack::Cursor cursor;
  for (Eigen::Index k = a; k < b; ++k) {
    T* res = residual + (k - part_begin) * channels;
    for (int c = 0; c < channels; ++c) {
      if (!d.sampled(k, c)) {
        res[c] = T(0);
        continue;
      }
      T model = diverged ? T(0) : x(d.channel_state[c]);
      if (c == d.rate_channel) model += plant.e->sensor_bias;
      T diff = model - T(d.measured(k, c));
      if (c == d.heading_channel) {
        const double turns = std::round(ValueOf(diff) / (2.0 * std::numbers::pi));
        diff -= T(turns * 2.0 * std::numbers::pi);
      }
      res[c] = diff / d.scale[c];
    }
    if (k + 1 == b || diverged) continue;
    const double span = d.times[k + 1] - d.times[k];
    const int n = std::max(1, static_cast<int>(std::ceil(span / d.max_step - 1e-9)));
    const double h = span / n;
    for (int s = 0; s < n; ++s) {
      d.inputs.DelayedMean(d.times[k] + s * h, h, plant.delay, plant.e->input_delays_s, u.data(),
                           cursor);
      stepper.Step(u.data(), h, x);
    }
    for (int i = 0; i < N; ++i) {
      const double v = ValueOf(x(i));
      if (!std::isfinite(v) || std::abs(v) > kBound) diverged = true;
    }
  }
  return diverged;
}

// The actuators' lag states at row `at`, filtered exactly (zero-order hold) from the commands
// since row `from` (or the last 12 time constants), where they start at the command; the
// command itself without a lag.
template <Vessel V, typename T>
void LagStatesAt(const MeasuredData& d, Eigen::Index from, Eigen::Index at,
                 const EffectPlant<V, T>& plant, T* lag) {
  std::array<T, V::kInputs> u;
  InputTrack::Cursor cursor;
  auto command = [&](double t, double h) {
    d.inputs.DelayedMean(t, h, plant.delay, plant.e->input_delays_s, u.data(), cursor);
    for (int i = 0; i < V::kInputs; ++i) {
      if (ValueOf(u[i]) > plant.limits[i]) u[i] = T(plant.limits[i]);
      if (ValueOf(u[i]) < -plant.limits[i]) u[i] = T(-plant.limits[i]);
    }
  };
  const T tau = plant.e->lag_time_constant_s;
  if (!(ValueOf(tau) > 0.0)) {
    command(d.times[at], d.max_step);
    for (int i = 0; i < V::kInputs; ++i) lag[i] = u[i];
    return;
  }
  using std::exp;
  // The memory of the lag fades as exp(-t / tau): start 12 tau back (6e-6 of it left).
  const double window = 12.0 * ValueOf(tau);
  while (from < at && d.times[at] - d.times[from] > window) ++from;
  command(d.times[from], d.max_step);
  for (int i = 0; i < V::kInputs; ++i) lag[i] = u[i];
  for (Eigen::Index k = from; k < at; ++k) {
    const double span = d.times[k + 1] - d.times[k];
    const int n = std::max(1, static_cast<int>(std::ceil(span / d.max_step - 1e-9)));
    const double h = span / n;
    const T decay = exp(-h / tau);
    for (int s = 0; s < n; ++s) {
      command(d.times[k] + s * h, h);
      for (int i = 0; i < V::kInputs; ++i) lag[i] = u[i] + (lag[i] - u[i]) * decay;
    }
  }
}

// One segment of a part from the vessel state x0 (V::kStates values) at its first row.
template <Vessel V, typename T>
void SegmentRollout(const MeasuredData& d, const Part& part, size_t segment,
                    const EffectPlant<V, T>& plant, const T* x0, T* residual) {
  const auto [a, b] = SegmentRows(part, segment);
  typename PlantStepper<V, T>::State x;
  for (int i = 0; i < V::kStates; ++i) x(i) = x0[i];
  LagStatesAt<V, T>(d, part.begin, a, plant, x.data() + V::kStates);
  RolloutRows<V, T>(d, a, a, b, plant, x, residual);
}

// The whole part with resets; `starts` (if given) receives the vessel state at each segment's
// first row, after the reset.
template <Vessel V, typename T>
void ResetRollout(const MeasuredData& d, const Part& part, const std::array<double, V::kParams>& p,
                  const EffectValues<T>& e, T* residual,
                  std::vector<std::array<double, V::kStates>>* starts = nullptr) {
  const EffectPlant<V, T> plant(d, p, e);
  typename PlantStepper<V, T>::State x;
  for (int i = 0; i < V::kStates; ++i) x(i) = T(d.fallback_states(part.begin, i));
  LagStatesAt<V, T>(d, part.begin, part.begin, plant, x.data() + V::kStates);
  for (size_t s = 0; s < part.starts.size(); ++s) {
    const auto [a, b] = SegmentRows(part, s);
    for (int i = 0; i < V::kStates; ++i) {
      const int c = d.state_channel[i];
      if (c >= 0 && d.sampled(a, c)) {
        x(i) = T(d.reset(a, c));
        if (c == d.rate_channel) x(i) -= e.sensor_bias;
      } else if (!std::isfinite(ValueOf(x(i))) || std::abs(ValueOf(x(i))) > 1e7) {
        x(i) = T(d.fallback_states(a, i));
      }
    }
    if (starts != nullptr) {
      std::array<double, V::kStates> x0;
      for (int i = 0; i < V::kStates; ++i) x0[i] = ValueOf(x(i));
      starts->push_back(x0);
    }
    if (RolloutRows<V, T>(d, part.begin, a, b, plant, x, residual))
      LagStatesAt<V, T>(d, part.begin, b < part.end ? b : a, plant, x.data() + V::kStates);
  }
}

}  // namespace usvid::diagnosis
