// What the sensors log of a simulated run, in order (docs/data.md, "What the sensors add"): the
// waves' first-order motion on top of the simulated motion, Gaussian noise on the measured
// channels, each sensor's own rate, and its dropouts. One chain for `usvid simulate` and a
// suite's simulated records, so both log alike.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "sensors/dropouts.h"
#include "sensors/wave_motion.h"

namespace usvid {

struct SensorSpec {
  std::string waves;                  // HS[:TP[:FROM_DEG]]; "": calm
  double noise = 0.0;                 // level, as AddGaussianNoise takes it
  std::vector<std::string> rates;     // NAME=HZ items
  std::vector<std::string> dropouts;  // NAME=FRACTION items
};

// What the chain did, for a truth file.
struct SensorLog {
  std::optional<WaveSea> sea;
  double hull_length_m = 0.0;
  std::vector<double> noise_sd;  // per measured channel
  std::map<std::string, double> rates;
  std::vector<Dropout> dropouts;
};

// Runs the chain on `data` in place; `measured` are the channels that get noise, `hull_length_m`
// the waves' hull (WaveHullLength). InputError on a bad item, naming it.
SensorLog LogAsSensors(Dataset& data, const std::vector<std::string>& measured,
                       const SensorSpec& spec, double hull_length_m, uint64_t seed);

}  // namespace usvid
