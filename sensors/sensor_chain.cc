#include "sensors/sensor_chain.h"

#include "sensors/noise.h"
#include "sensors/sample_rates.h"

namespace usvid {

SensorLog LogAsSensors(Dataset& data, const std::vector<std::string>& measured,
                       const SensorSpec& spec, double hull_length_m, uint64_t seed) {
  SensorLog log;
  log.hull_length_m = hull_length_m;
  if (!spec.waves.empty()) {
    log.sea = ParseWaveSea(spec.waves, seed, "--waves '" + spec.waves + "'");
    AddWaveMotion(data, *log.sea, hull_length_m, seed);
  }
  log.noise_sd = AddGaussianNoise(data, measured, spec.noise, seed);
  log.rates = ParseSampleRates(spec.rates, data);
  ApplySampleRates(data, log.rates);
  log.dropouts = ParseDropouts(spec.dropouts);
  ApplyDropouts(data, log.dropouts, seed);
  return log;
}

}  // namespace usvid
