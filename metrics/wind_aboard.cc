#include "metrics/wind_aboard.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "maneuvers/true_wind.h"
#include "simulation/recorded_inputs.h"

namespace usvid {
namespace {

constexpr std::array<const char*, 4> kWindInputs = {"wind_speed", "wind_direction", "wind_u",
                                                    "wind_v"};

int IndexOf(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::ranges::find(names, name);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

}  // namespace

WindAboard::WindAboard(const Dataset& data, const std::vector<std::string>& inputs,
                       const std::vector<std::string>& channels) {
  for (size_t k = 0; k < kWindInputs.size(); ++k)
    if (const int i = IndexOf(inputs, kWindInputs[k]); i >= 0)
      wind_inputs_.emplace_back(i, static_cast<int>(k));
  psi_ = IndexOf(channels, "psi");
  u_ = IndexOf(channels, "u");
  v_ = IndexOf(channels, "v");
  if (wind_inputs_.empty() || psi_ < 0) return;
  std::optional<std::array<Eigen::VectorXd, 2>> air = RecordedAirOverGround(data);
  if (!air) return;
  air_north_ = std::move((*air)[0]);
  air_east_ = std::move((*air)[1]);
  engaged_ = true;
}

std::array<double, 4> WindAboard::Values(double north, double east, double psi, double u,
                                         double v) {
  const std::array<double, 2> rel = RelativeWindOf({north, east}, psi, u, v);
  // data.md#derived-channels: the air's velocity past the ship, -V [cos gamma, sin gamma].
  return {rel[0], rel[1], -rel[0] * std::cos(rel[1]), -rel[0] * std::sin(rel[1])};
}

}  // namespace usvid
