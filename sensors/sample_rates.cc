#include "sensors/sample_rates.h"

#include <cmath>

#include "core/error.h"
#include "core/parse_number.h"

namespace usvid {
namespace {

const std::map<std::string, std::vector<std::string>>& Groups() {
  static const std::map<std::string, std::vector<std::string>> groups = {
      {"imu", {"psi", "u", "v", "r", "x"}},
      {"gps", {"north", "east", "U", "chi"}},
      {"jet", {"rpm", "nozzle_angle", "bucket_position"}},
  };
  return groups;
}

}  // namespace

std::vector<std::pair<std::string, double>> ParseRateItems(const std::vector<std::string>& items) {
  std::vector<std::pair<std::string, double>> out;
  for (const std::string& item : items) {
    const std::string where = "--rates '" + item + "': ";
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw InputError(where + "expected NAME=HZ");
    const ParsedNumber hz = ParseNumber(item.substr(eq + 1));
    if (hz.status != NumberStatus::kOk || !(hz.value > 0))
      throw InputError(where + "the rate must be a positive number of Hz");
    out.emplace_back(item.substr(0, eq), hz.value);
  }
  return out;
}

std::map<std::string, double> ParseSampleRates(const std::vector<std::string>& items,
                                               const Dataset& data) {
  std::map<std::string, double> rates;
  const std::vector<std::pair<std::string, double>> parsed = ParseRateItems(items);
  for (size_t i = 0; i < parsed.size(); ++i) {
    const auto& [name, hz] = parsed[i];
    const std::vector<std::string> channels = SensorChannels(name, data);
    if (channels.empty())
      throw InputError("--rates '" + items[i] + "': no group or channel '" + name +
                       "' (groups: imu, gps, jet)");
    for (const std::string& c : channels) rates[c] = hz;
  }
  return rates;
}

std::vector<std::string> SensorChannels(const std::string& name, const Dataset& data) {
  std::vector<std::string> out;
  const auto group = Groups().find(name);
  if (group == Groups().end()) {
    if (data.Has(name)) out.push_back(name);
    return out;
  }
  for (const std::string& c : group->second)
    if (data.Has(c)) out.push_back(c);
  return out;
}

void ApplySampleRates(Dataset& data, const std::map<std::string, double>& rates) {
  if (data.rows() == 0) return;
  const double t0 = data.t()(0);
  for (const auto& [name, hz] : rates) {
    const Channel& c = data.Get(name);
    Eigen::Array<bool, Eigen::Dynamic, 1> sampled = c.sampled();
    long next_period = 0;
    for (Eigen::Index i = 0; i < data.rows(); ++i) {
      const double periods = (data.t()(i) - t0) * hz;
      // A small tolerance so that exact multiples (0.2 s at 5 Hz) count as due.
      if (periods + 1e-9 >= static_cast<double>(next_period)) {
        next_period = static_cast<long>(std::floor(periods + 1e-9)) + 1;
      } else {
        sampled(i) = false;
      }
    }
    data.Set(name, c.values(), std::move(sampled));
  }
}

}  // namespace usvid
