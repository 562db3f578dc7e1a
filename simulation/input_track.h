// A commanded input signal under zero-order hold: samples (t_k, u_k) appended in time order;
// the command in force at t is the last sample at or before t (the first one before t_0).
// Lookups through a Cursor that move forward in time are O(1) amortised; the track itself is
// never written by a lookup, so threads share one track, each rollout with its own cursor.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace usvid {

class InputTrack {
 public:
  // Where the last lookup landed: one per rollout (per thread).
  class Cursor {
    friend class InputTrack;
    size_t k_ = 0;
  };

  explicit InputTrack(int inputs) : inputs_(inputs) {}

  int inputs() const { return inputs_; }
  size_t size() const { return times_.size(); }
  double time(size_t k) const { return times_[k]; }

  void Append(double t, std::span<const double> u) {
    times_.push_back(t);
    values_.insert(values_.end(), u.begin(), u.begin() + inputs_);
  }

  // Pointer to the `inputs()` values in force at t; the track must not be empty.
  const double* At(double t, Cursor& c) const {
    const size_t n = times_.size();
    // The cursor's sample or the next one: O(1). Anything else: a binary search.
    if (c.k_ < n && times_[c.k_] <= t && c.k_ + 1 < n && times_[c.k_ + 1] <= t) ++c.k_;
    if (c.k_ >= n || times_[c.k_] > t || (c.k_ + 1 < n && times_[c.k_ + 1] <= t)) {
      const auto it = std::upper_bound(times_.begin(), times_.end(), t);
      c.k_ = it == times_.begin() ? 0 : static_cast<size_t>(it - times_.begin()) - 1;
    }
    return values_.data() + c.k_ * inputs_;
  }
  const double* At(double t) const {
    Cursor c;
    return At(t, c);
  }

  // The commands in force at t - delay (and, per input, t - delay - extra[i]) into u.
  template <typename T>
  void Delayed(double t, double delay, const std::vector<double>& extra, T* u, Cursor& c) const {
    const double* cmd = At(t - delay, c);
    for (int i = 0; i < inputs_; ++i) u[i] = T(cmd[i]);
    if (extra.empty()) return;
    for (int i = 0; i < inputs_ && i < static_cast<int>(extra.size()); ++i)
      if (extra[i] != 0.0) u[i] = T(At(t - delay - extra[i])[i]);
  }

  // The mean over [t, t + h] of the commands in force at (time - delay [- extra[i]]): a
  // zero-order-hold signal shifted by any delay, as one value per step, so that a simulation
  // with step h is continuous in the delay.
  template <typename T>
  void DelayedMean(double t, double h, double delay, const std::vector<double>& extra, T* u,
                   Cursor& c) const {
    for (int i = 0; i < inputs_; ++i) {
      const double shift = delay + (i < static_cast<int>(extra.size()) ? extra[i] : 0.0);
      double a = t - shift;
      const double end = a + h;
      double sum = 0.0;
      while (a < end) {
        // Seek the sample in force at a and the time the next one takes over.
        const double* cmd = At(a, c);
        const double next = c.k_ + 1 < times_.size() ? times_[c.k_ + 1] : INFINITY;
        const double until = std::min(end, next);
        sum += cmd[i] * (until - a);
        a = until;
      }
      u[i] = T(sum / h);
    }
  }

  // Largest |u_i| over the track, per input (the peak command).
  std::vector<double> PeakAbs() const {
    std::vector<double> peak(inputs_, 0.0);
    for (size_t k = 0; k < times_.size(); ++k)
      for (int i = 0; i < inputs_; ++i)
        peak[i] = std::max(peak[i], std::abs(values_[k * inputs_ + i]));
    return peak;
  }

 private:
  int inputs_;
  std::vector<double> times_;
  std::vector<double> values_;
};

}  // namespace usvid
