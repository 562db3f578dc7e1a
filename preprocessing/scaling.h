// Z-scores per channel, stored so they can be undone: x_scaled = (x - mean) / sd. Fitted on
// training data only and applied unchanged to held-out data. A constant channel keeps sd = 1.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/dataset.h"

namespace usvid {

class ZScore {
 public:
  // Mean and sd of each channel's sampled values.
  static ZScore Fit(const Dataset& data, const std::vector<std::string>& channels);

  Dataset Apply(const Dataset& data) const;
  Dataset Undo(const Dataset& data) const;
  double Mean(const std::string& channel) const { return stats_.at(channel).first; }
  double Sd(const std::string& channel) const { return stats_.at(channel).second; }

  nlohmann::json ToJson() const;
  static ZScore FromJson(const nlohmann::json& value);

 private:
  Dataset Map(const Dataset& data, bool forward) const;
  std::map<std::string, std::pair<double, double>> stats_;  // mean, sd
};

}  // namespace usvid
