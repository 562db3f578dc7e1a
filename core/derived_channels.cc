#include "core/derived_channels.h"

#include <cmath>

namespace usvid {

void AddSpeedAndCourse(Dataset& data) {
  if (!data.Has("u") || !data.Has("v")) return;
  // Set() may move the channels: no reference into `data` lives across it.
  if (!data.Has("U")) {
    const Channel& u = data.Get("u");
    const Channel& v = data.Get("v");
    Eigen::VectorXd speed = (u.values.array().square() + v.values.array().square()).sqrt().matrix();
    Eigen::ArrayX<bool> sampled = u.sampled && v.sampled;
    data.Set("U", std::move(speed), std::move(sampled));
  }
  if (!data.Has("chi") && data.Has("psi")) {
    const Channel& u = data.Get("u");
    const Channel& v = data.Get("v");
    const Channel& psi = data.Get("psi");
    Eigen::VectorXd course(data.rows());
    for (Eigen::Index k = 0; k < data.rows(); ++k)
      course(k) = psi.values(k) + std::atan2(v.values(k), u.values(k));
    Eigen::ArrayX<bool> sampled = u.sampled && v.sampled && psi.sampled;
    data.Set("chi", std::move(course), std::move(sampled));
  }
}

void AddWindComponents(Dataset& data) {
  if (!data.Has("wind_speed") || !data.Has("wind_direction")) return;
  if (data.Has("wind_u") && data.Has("wind_v")) return;
  const Channel& speed = data.Get("wind_speed");
  const Channel& from = data.Get("wind_direction");
  Eigen::VectorXd along = -(speed.values.array() * from.values.array().cos()).matrix();
  Eigen::VectorXd across = -(speed.values.array() * from.values.array().sin()).matrix();
  const Eigen::ArrayX<bool> sampled = speed.sampled && from.sampled;
  // Set() may move the channels: `speed` and `from` are not read after the first.
  if (!data.Has("wind_u")) data.Set("wind_u", std::move(along), sampled);
  if (!data.Has("wind_v")) data.Set("wind_v", std::move(across), sampled);
}

void AddDerivedChannels(Dataset& data) {
  AddSpeedAndCourse(data);
  AddWindComponents(data);
}

bool CanDerive(const Dataset& data, const std::string& name) {
  if (name == "U") return data.Has("u") && data.Has("v");
  if (name == "chi") return data.Has("u") && data.Has("v") && data.Has("psi");
  if (name == "wind_u" || name == "wind_v")
    return data.Has("wind_speed") && data.Has("wind_direction");
  return false;
}

std::string DerivedFrom(const std::string& name) {
  if (name == "U") return "u and v";
  if (name == "chi") return "u, v and psi";
  if (name == "wind_u" || name == "wind_v") return "wind_speed and wind_direction";
  return "";
}

}  // namespace usvid
