#include "core/derived_channels.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace usvid {

void AddSpeedAndCourse(Dataset& data) {
  if (!data.Has("u") || !data.Has("v")) return;
  // Set() may move the channels: no reference into `data` lives across it.
  if (!data.Has("U")) {
    const Channel& u = data.Get("u");
    const Channel& v = data.Get("v");
    Eigen::VectorXd speed =
        (u.values().array().square() + v.values().array().square()).sqrt().matrix();
    Eigen::ArrayX<bool> sampled = u.sampled() && v.sampled();
    data.Set("U", std::move(speed), std::move(sampled));
  }
  if (!data.Has("chi") && data.Has("psi")) {
    const Channel& u = data.Get("u");
    const Channel& v = data.Get("v");
    const Channel& psi = data.Get("psi");
    Eigen::VectorXd course(data.rows());
    for (Eigen::Index k = 0; k < data.rows(); ++k)
      course(k) = psi.Value(k) + std::atan2(v.Value(k), u.Value(k));
    Eigen::ArrayX<bool> sampled = u.sampled() && v.sampled() && psi.sampled();
    data.Set("chi", std::move(course), std::move(sampled));
  }
}

void AddWindComponents(Dataset& data) {
  if (!data.Has("wind_speed") || !data.Has("wind_direction")) return;
  if (data.Has("wind_u") && data.Has("wind_v")) return;
  const Channel& speed = data.Get("wind_speed");
  const Channel& from = data.Get("wind_direction");
  Eigen::VectorXd along = -(speed.values().array() * from.values().array().cos()).matrix();
  Eigen::VectorXd across = -(speed.values().array() * from.values().array().sin()).matrix();
  const Eigen::ArrayX<bool> sampled = speed.sampled() && from.sampled();
  // Set() may move the channels: `speed` and `from` are not read after the first.
  if (!data.Has("wind_u")) data.Set("wind_u", std::move(along), sampled);
  if (!data.Has("wind_v")) data.Set("wind_v", std::move(across), sampled);
}

void AddDerivedChannels(Dataset& data) {
  AddSpeedAndCourse(data);
  AddWindComponents(data);
}

namespace {

// Each derived channel and the logged channels it is computed from.
const std::vector<std::string>* SourcesOf(const std::string& name) {
  static const std::map<std::string, std::vector<std::string>> sources = {
      {"U", {"u", "v"}},
      {"chi", {"u", "v", "psi"}},
      {"wind_u", {"wind_speed", "wind_direction"}},
      {"wind_v", {"wind_speed", "wind_direction"}}};
  const auto it = sources.find(name);
  return it == sources.end() ? nullptr : &it->second;
}

}  // namespace

bool CanDerive(const Dataset& data, const std::string& name) {
  const std::vector<std::string>* from = SourcesOf(name);
  return from != nullptr &&
         std::all_of(from->begin(), from->end(), [&](const std::string& c) { return data.Has(c); });
}

std::string DerivedFrom(const std::string& name) {
  const std::vector<std::string>* from = SourcesOf(name);
  std::string out;
  for (size_t i = 0; from != nullptr && i < from->size(); ++i)
    out += (i == 0 ? "" : i + 1 == from->size() ? " and " : ", ") + (*from)[i];
  return out;
}

}  // namespace usvid
