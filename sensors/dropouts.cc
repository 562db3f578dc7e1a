#include "sensors/dropouts.h"

#include <random>

#include "core/error.h"
#include "core/parse_number.h"
#include "sensors/sample_rates.h"

namespace usvid {

std::vector<Dropout> ParseDropouts(const std::vector<std::string>& items) {
  std::vector<Dropout> out;
  for (const std::string& item : items) {
    const std::string where = "--dropouts '" + item + "': ";
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError(where + "expected NAME=FRACTION");
    const ParsedNumber f = ParseNumber(item.substr(eq + 1));
    if (f.status != NumberStatus::kOk || !(f.value >= 0.0 && f.value <= 0.9))
      throw InputError(where + "the fraction lost must be a number in [0, 0.9]");
    out.push_back({item.substr(0, eq), f.value});
  }
  return out;
}

void ApplyDropouts(Dataset& data, const std::vector<Dropout>& dropouts, uint64_t seed) {
  for (const Dropout& d : dropouts) {
    const std::vector<std::string> channels = SensorChannels(d.sensor, data);
    if (channels.empty())
      throw InputError("--dropouts '" + d.sensor + "': no group or channel of that name " +
                       "(groups: imu, gps, jet)");
    if (d.fraction <= 0.0 || data.rows() == 0) continue;
    // One stream per sensor, so adding a sensor does not move another's gaps.
    std::seed_seq seq(d.sensor.begin(), d.sensor.end());
    std::vector<uint32_t> salt(2);
    seq.generate(salt.begin(), salt.end());
    std::mt19937_64 rng(seed ^ (static_cast<uint64_t>(salt[0]) << 32 | salt[1]));
    std::exponential_distribution<double> gap(1.0 / kMeanGapS),
        working(d.fraction / (kMeanGapS * (1.0 - d.fraction)));
    Eigen::Array<bool, Eigen::Dynamic, 1> kept =
        Eigen::Array<bool, Eigen::Dynamic, 1>::Constant(data.rows(), true);
    const Eigen::VectorXd& t = data.t();
    double lost_from = t(0) + working(rng), lost_to = lost_from + gap(rng);
    for (Eigen::Index i = 0; i < data.rows(); ++i) {
      while (t(i) >= lost_to) {
        lost_from = lost_to + working(rng);
        lost_to = lost_from + gap(rng);
      }
      kept(i) = t(i) < lost_from;
    }
    for (const std::string& name : channels) {
      const Channel& c = data.Get(name);
      data.Set(name, c.values(), c.sampled() && kept);
    }
  }
}

nlohmann::json DropoutsToJson(const std::vector<Dropout>& dropouts) {
  nlohmann::json out = nlohmann::json::object();
  for (const Dropout& d : dropouts) out[d.sensor] = d.fraction;
  if (!dropouts.empty()) out["mean_gap_s"] = kMeanGapS;
  return out;
}

}  // namespace usvid
