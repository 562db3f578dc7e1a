#include "simulation/logged_disturbances.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "maneuvers/true_wind.h"

namespace usvid {

const std::vector<std::string>& LoggableDisturbances() {
  static const std::vector<std::string> names = {"wind", "current"};
  return names;
}

std::vector<std::string> LoggedInputChannels(const std::vector<std::string>& disturbances) {
  std::vector<std::string> channels;
  for (const std::string& d : disturbances) {
    if (d == "wind") channels.insert(channels.end(), {"wind_speed", "wind_u", "wind_v"});
    if (d == "current") channels.insert(channels.end(), {"current_u", "current_v"});
  }
  return channels;
}

void CheckLoggedDisturbances(const std::vector<std::string>& disturbances, bool has_gusts,
                             const std::vector<Effect>& effects, const std::string& where) {
  const bool has_current =
      std::ranges::any_of(effects, [](const Effect& e) { return e.kind == EffectKind::kCurrent; });
  const std::vector<std::string>& known = LoggableDisturbances();
  for (const std::string& d : disturbances) {
    if (std::ranges::find(known, d) == known.end())
      throw InputError(where + ": '" + d + "' is no disturbance a record can log (wind, current)");
    if (std::ranges::count(disturbances, d) > 1)
      throw InputError(where + ": '" + d + "' is named twice");
    if (d == "wind" && !has_gusts)
      throw InputError(where + ": 'wind' logs the gusty wind, and no gusts are set");
    if (d == "current" && !has_current)
      throw InputError(where + ": 'current' logs the current, and no current effect is set");
  }
}

std::vector<std::string> LogDisturbances(Dataset& data,
                                         const std::vector<std::string>& disturbances,
                                         const WindGusts* gusts, uint64_t seed,
                                         const EffectValues<double>& effects) {
  std::vector<std::string> added;
  if (disturbances.empty()) return added;
  for (const char* state : {"psi", "u", "v"})
    if (!data.Has(state))
      throw InputError(std::string("logged disturbances: the record has no '") + state + "'");
  const Eigen::Index n = data.rows();
  for (const std::string& d : disturbances) {
    // Read afresh for each: Set() may move the channels.
    const Eigen::VectorXd& t = data.t();
    const Channel& psi = data.Get("psi");
    const Channel& u = data.Get("u");
    const Channel& v = data.Get("v");
    if (d == "wind") {
      if (gusts == nullptr) throw InputError("logged disturbances: 'wind' without gusts");
      const GustySpeed speed(gusts->wind, seed);
      Eigen::VectorXd wind_speed(n), wind_direction(n);
      for (Eigen::Index k = 0; k < n; ++k) {
        const std::array<double, 2> rel =
            RelativeWind(speed(t(k)), gusts->wind.from_rad, psi.Value(k), u.Value(k), v.Value(k));
        wind_speed(k) = rel[0];
        wind_direction(k) = rel[1];
      }
      data.Set("wind_speed", std::move(wind_speed));
      data.Set("wind_direction", std::move(wind_direction));
      added.insert(added.end(), {"wind_speed", "wind_direction"});
    } else if (d == "current") {
      Eigen::VectorXd along(n), across(n);
      for (Eigen::Index k = 0; k < n; ++k) {
        const double c = std::cos(psi.Value(k)), s = std::sin(psi.Value(k));
        along(k) = effects.current_north * c + effects.current_east * s;
        across(k) = -effects.current_north * s + effects.current_east * c;
      }
      data.Set("current_u", std::move(along));
      data.Set("current_v", std::move(across));
      added.insert(added.end(), {"current_u", "current_v"});
    }
  }
  return added;
}

}  // namespace usvid
