// Multi-rate sensors: a channel sampled at f Hz keeps the rows at which a new sample period
// starts (the first row at or after t0 + k / f) and leaves the rest empty (not sampled), as a
// real multi-rate log does. Groups name the usual sensors:
//   imu = psi, u, v, r (and the msd's x, v);  gps = north, east, U, chi;
//   jet = the actuator feedback states (rpm, nozzle_angle, bucket_position).
// A spec is "NAME=HZ,..." with group or channel names, e.g. "imu=50,gps=5,jet=10".
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/dataset.h"

namespace usvid {

// Each item's name and rate [Hz], in order; throws InputError on an item that is not NAME=HZ
// with HZ > 0.
std::vector<std::pair<std::string, double>> ParseRateItems(const std::vector<std::string>& items);

// Channel -> rate [Hz]; throws InputError on a bad item or a channel the data lack.
std::map<std::string, double> ParseSampleRates(const std::vector<std::string>& items,
                                               const Dataset& data);

// The channels of `data` that a group or channel name stands for; empty when it names neither.
std::vector<std::string> SensorChannels(const std::string& name, const Dataset& data);

void ApplySampleRates(Dataset& data, const std::map<std::string, double>& rates);

}  // namespace usvid
