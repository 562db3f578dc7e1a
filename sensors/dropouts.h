// Sensor dropouts: a sensor that loses samples in gaps, as a GPS does under a bridge or in a
// harbour, or a telemetry link does at range. Each named sensor (a group of sample_rates.h: imu,
// gps, jet; or one channel) alternates between working and lost periods, both exponentially
// distributed: lost periods of mean kMeanGapS, working periods of mean kMeanGapS (1 - f) / f,
// so that a share f of the time is lost. Every channel of a group loses the same rows (one
// receiver); each group draws its own gaps from the seed and its name. A lost row is not
// sampled: the channel's other rows are untouched, and readers see a gap, not a value.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/dataset.h"

namespace usvid {

inline constexpr double kMeanGapS = 2.0;

struct Dropout {
  std::string sensor;   // a group or channel name
  double fraction = 0;  // share of the time lost, in [0, 0.9]
};

// "NAME=FRACTION" items (`--dropouts gps=0.05`); InputError naming the item for a fraction
// outside [0, 0.9].
std::vector<Dropout> ParseDropouts(const std::vector<std::string>& items);

// Removes the lost rows' samples; InputError for a sensor naming no channel of `data`.
void ApplyDropouts(Dataset& data, const std::vector<Dropout>& dropouts, uint64_t seed);

nlohmann::json DropoutsToJson(const std::vector<Dropout>& dropouts);

}  // namespace usvid
