#include "simulation/recorded_inputs.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"
#include "maneuvers/true_wind.h"

namespace usvid {

InputTrack RecordedInputs(const Dataset& data, const VesselInfo& info) {
  const auto inputs = static_cast<int>(info.inputs.size());
  std::vector<const Channel*> channels;
  for (size_t i = 0; i < info.inputs.size(); ++i) {
    const std::string& name = info.inputs[i];
    const Channel* c = data.Find(name);
    if (c == nullptr && info.IsMeasuredInput(i)) {
      channels.push_back(nullptr);  // no wind logged: none
      continue;
    }
    if (c == nullptr)
      throw InputError(data.SourcePrefix() + "no input column '" + name + "' for vessel " +
                       info.name);
    channels.push_back(c);
  }
  std::vector<double> u(inputs, 0.0);
  for (int i = 0; i < inputs; ++i) {
    if (channels[i] == nullptr) u[i] = info.actuation.neutral.at(i);
    for (Eigen::Index k = 0; k < data.rows() && channels[i] != nullptr; ++k)
      if (channels[i]->IsSampled(k)) {
        u[i] = channels[i]->Value(k);
        break;
      }
  }
  InputTrack track(inputs);
  for (Eigen::Index k = 0; k < data.rows(); ++k) {
    for (int i = 0; i < inputs; ++i)
      if (channels[i] != nullptr && channels[i]->IsSampled(k)) u[i] = channels[i]->Value(k);
    track.Append(data.t()(k), u);
  }
  return track;
}

std::optional<std::array<Eigen::VectorXd, 2>> RecordedAirOverGround(const Dataset& data) {
  for (const char* c : {"wind_speed", "wind_direction", "psi", "u", "v"})
    if (!data.Has(c)) return std::nullopt;
  const Channel& speed = data.Get("wind_speed");
  const Channel& from = data.Get("wind_direction");
  const Channel& psi = data.Get("psi");
  const Channel& u = data.Get("u");
  const Channel& v = data.Get("v");
  const Eigen::Index rows = data.rows();
  std::array<Eigen::VectorXd, 2> air = {Eigen::VectorXd::Constant(rows, NAN),
                                        Eigen::VectorXd::Constant(rows, NAN)};
  // A record whose wind reads 0 throughout logs none (a simulation without wind writes 0, which
  // the wind model takes for calm): there is no true wind to take from it.
  bool any_wind = false;
  for (Eigen::Index k = 0; k < rows && !any_wind; ++k)
    any_wind = speed.IsSampled(k) && speed.Value(k) != 0.0;
  if (!any_wind) return std::nullopt;
  Eigen::Index first = -1;
  for (Eigen::Index k = 0; k < rows; ++k) {
    if (speed.IsSampled(k) && from.IsSampled(k) && psi.IsSampled(k) && u.IsSampled(k) &&
        v.IsSampled(k)) {
      const std::array<double, 2> a =
          AirOverGround(speed.Value(k), from.Value(k), psi.Value(k), u.Value(k), v.Value(k));
      air[0](k) = a[0];
      air[1](k) = a[1];
      if (first < 0) first = k;
    } else if (k > 0) {
      air[0](k) = air[0](k - 1);
      air[1](k) = air[1](k - 1);
    }
  }
  if (first < 0) return std::nullopt;
  for (Eigen::VectorXd& a : air) a.head(first).setConstant(a(first));
  return air;
}

std::optional<InputTrack> WindOverGround(const Dataset& data, const VesselInfo& info,
                                         const InputTrack& track) {
  const auto index = [&](const std::string& name) {
    const auto it = std::ranges::find(info.inputs, name);
    return it == info.inputs.end() ? -1 : static_cast<int>(it - info.inputs.begin());
  };
  const int speed = index("wind_speed"), from = index("wind_direction");
  if (speed < 0 || from < 0) return std::nullopt;
  const std::optional<std::array<Eigen::VectorXd, 2>> air = RecordedAirOverGround(data);
  if (!air) return std::nullopt;
  InputTrack out(track.inputs());
  std::vector<double> row(track.inputs());
  InputTrack::Cursor cursor;
  for (Eigen::Index k = 0; k < data.rows(); ++k) {
    const double* in = track.At(data.t()(k), cursor);
    row.assign(in, in + track.inputs());
    row[speed] = (*air)[0](k);
    row[from] = (*air)[1](k);
    out.Append(data.t()(k), row);
  }
  return out;
}

}  // namespace usvid
