// Multi-rate data onto one uniform time base. Each channel is interpolated from its own samples
// (linear, or natural cubic spline within each stretch of samples without a long gap); grid
// points inside a gap longer than max_gap_s, or outside the channel's first and last sample,
// stay unsampled rather than invented. The report says, per channel, what was done.
#pragma once

#include <string>
#include <vector>

#include "core/dataset.h"

namespace usvid {

enum class Interpolation { kLinear, kCubicSpline };

struct ResampleOptions {
  double rate_hz = 20.0;
  Interpolation interpolation = Interpolation::kCubicSpline;
  // Longest stretch between two samples that is interpolated across; <= 0: four times the
  // channel's median sample interval.
  double max_gap_s = 0.0;
  // The channels to resample; empty: every channel. The others are left out of the result.
  std::vector<std::string> channels;
};

struct ChannelResampling {
  std::string channel;
  long samples_in = 0;
  double median_interval_s = 0.0;
  long gaps = 0;       // stretches longer than the limit, left unsampled
  long unsampled = 0;  // grid points left unsampled
};

struct ResampleReport {
  std::vector<ChannelResampling> channels;
  std::vector<std::string> Summary() const;
};

// Throws InputError for a non-positive rate or a channel with fewer than two samples.
Dataset Resample(const Dataset& data, const ResampleOptions& options,
                 ResampleReport* report = nullptr);

}  // namespace usvid
