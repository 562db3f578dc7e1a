#include "preprocessing/scaling.h"

#include <cmath>

#include "core/error.h"

namespace usvid {

ZScore ZScore::Fit(const Dataset& data, const std::vector<std::string>& channels) {
  ZScore z;
  for (const std::string& name : channels) {
    const Channel& c = data.Get(name);
    const double n = static_cast<double>(c.SampleCount());
    if (n < 2) throw InputError("z-score: channel '" + name + "' has fewer than two samples");
    const Eigen::ArrayXd v = c.sampled().select(c.values().array(), 0.0);
    const double mean = v.sum() / n;
    const double sd = std::sqrt(c.sampled().select((v - mean).square(), 0.0).sum() / (n - 1));
    z.stats_[name] = {mean, sd > 0 ? sd : 1.0};
  }
  return z;
}

Dataset ZScore::Map(const Dataset& data, bool forward) const {
  Dataset out = data;
  for (const auto& [name, ms] : stats_) {
    if (!data.Has(name)) continue;
    const Channel& c = data.Get(name);
    const Eigen::VectorXd v = forward ? Eigen::VectorXd((c.values().array() - ms.first) / ms.second)
                                      : Eigen::VectorXd(c.values().array() * ms.second + ms.first);
    out.Set(name, v, c.sampled());
  }
  return out;
}

Dataset ZScore::Apply(const Dataset& data) const { return Map(data, true); }
Dataset ZScore::Undo(const Dataset& data) const { return Map(data, false); }

nlohmann::json ZScore::ToJson() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, ms] : stats_) j[name] = {{"mean", ms.first}, {"sd", ms.second}};
  return j;
}

ZScore ZScore::FromJson(const nlohmann::json& value) {
  ZScore z;
  for (const auto& [name, ms] : value.items())
    z.stats_[name] = {ms.at("mean").get<double>(), ms.at("sd").get<double>()};
  return z;
}

}  // namespace usvid
