#include "importers/froude_scaling.h"

#include <array>
#include <cmath>
#include <string_view>

#include "core/error.h"
#include "core/parse_number.h"

namespace usvid {
namespace {

constexpr std::array<std::pair<std::string_view, Dimension>, 8> kNames = {{
    {"length", Dimension::kLength},
    {"speed", Dimension::kSpeed},
    {"rate", Dimension::kRate},
    {"revolutions", Dimension::kRevolutions},
    {"angle", Dimension::kAngle},
    {"acceleration", Dimension::kAcceleration},
    {"force", Dimension::kForce},
    {"moment", Dimension::kMoment},
}};

// The contract's channel names (docs/data.md) by dimension, and the extras the importers give
// (roll phi and its rate p, a propeller's thrust and torque).
constexpr std::array<std::pair<std::string_view, Dimension>, 28> kChannels = {{
    {"north", Dimension::kLength},
    {"east", Dimension::kLength},
    {"x", Dimension::kLength},
    {"y", Dimension::kLength},
    {"u", Dimension::kSpeed},
    {"v", Dimension::kSpeed},
    {"U", Dimension::kSpeed},
    {"vn", Dimension::kSpeed},
    {"ve", Dimension::kSpeed},
    {"wind_speed", Dimension::kSpeed},
    {"wind_speed_true", Dimension::kSpeed},
    {"r", Dimension::kRate},
    {"p", Dimension::kRate},
    {"n", Dimension::kRevolutions},
    {"rev", Dimension::kRevolutions},
    {"rpm", Dimension::kRevolutions},
    {"psi", Dimension::kAngle},
    {"phi", Dimension::kAngle},
    {"delta", Dimension::kAngle},
    {"chi", Dimension::kAngle},
    {"nozzle", Dimension::kAngle},
    {"wind_direction", Dimension::kAngle},
    {"wind_direction_true", Dimension::kAngle},
    {"tau_x", Dimension::kForce},
    {"tau_y", Dimension::kForce},
    {"thrust", Dimension::kForce},
    {"tau_n", Dimension::kMoment},
    {"torque", Dimension::kMoment},
}};

double Factor(Dimension d, double lambda) {
  switch (d) {
    case Dimension::kLength:
      return lambda;
    case Dimension::kSpeed:
      return std::sqrt(lambda);
    case Dimension::kRate:
    case Dimension::kRevolutions:
      return 1.0 / std::sqrt(lambda);
    case Dimension::kAngle:
    case Dimension::kAcceleration:
      return 1.0;
    case Dimension::kForce:
      return lambda * lambda * lambda;
    case Dimension::kMoment:
      return lambda * lambda * lambda * lambda;
  }
  return 1.0;
}

}  // namespace

Dimension ParseDimension(const std::string& name) {
  for (const auto& [n, d] : kNames)
    if (n == name) return d;
  throw InputError("'" + name +
                   "' is not a dimension (length, speed, rate, revolutions, angle, acceleration, "
                   "force, moment)");
}

std::string DimensionName(Dimension d) {
  for (const auto& [n, dim] : kNames)
    if (dim == d) return std::string(n);
  return "?";
}

Dimension DimensionOf(const std::string& channel, const std::map<std::string, Dimension>& given) {
  if (const auto it = given.find(channel); it != given.end()) return it->second;
  for (const auto& [n, d] : kChannels)
    if (n == channel) return d;
  throw InputError("--scale: channel '" + channel +
                   "' has no known dimension: name it by the data contract (docs/data.md) or "
                   "give one with --dimension " +
                   channel +
                   "=speed (length, speed, rate, "
                   "revolutions, angle, acceleration, force, moment)");
}

std::vector<ScaledChannel> FroudeScale(Dataset& data, double lambda,
                                       const std::map<std::string, Dimension>& given) {
  if (!(std::isfinite(lambda) && lambda > 0))
    throw InputError("--scale: the scale factor must be a finite number > 0, not " +
                     FormatNumber(lambda));
  for (const auto& [name, d] : given)
    if (!data.Has(name)) throw InputError("--dimension " + name + ": no channel '" + name + "'");
  // Every channel's factor first, so that an unknown one fails before anything is changed.
  std::vector<ScaledChannel> out;
  for (const Channel& c : data.channels()) {
    std::string base = c.name;
    int per_second = 0;
    while (base.size() > 4 && base.ends_with("_dot") && !given.contains(base)) {
      base.resize(base.size() - 4);
      ++per_second;
    }
    const Dimension d = DimensionOf(base, given);
    std::string what = DimensionName(d);
    for (int k = 0; k < per_second; ++k) what += " per second";
    out.push_back({c.name, what, Factor(d, lambda) / std::pow(std::sqrt(lambda), per_second)});
  }
  data.SetTime(data.t() * std::sqrt(lambda));
  for (const ScaledChannel& s : out) {
    const Channel& c = data.Get(s.channel);
    data.Set(s.channel, c.values() * s.factor, c.sampled());
  }
  return out;
}

}  // namespace usvid
