// Disturbances a simulated record logs for its methods to read: the measured track of the
// realistic benchmark (a suite's "logged", `usvid simulate --logged`;
// docs/compare.md#realistic-measured).
//   wind     the relative wind an anemometer aboard reads, from the gusty true wind
//            (simulation/wind_gusts.h) and the hull's true heading and velocity at each row:
//            wind_speed [m/s] and wind_direction [rad, where it blows from, clockwise from the
//            bow], as maneuvers/true_wind.h defines them. Identification derives the body
//            components wind_u, wind_v from these (core/derived_channels.h).
//   current  the water's velocity in body axes, as a Doppler log beside the GPS measures it
//            (speed through the water against speed over the ground): current_u, current_v
//            [m/s], the current (effects/effect.h: current_north, current_east) turned by the
//            true heading psi: current_u = c_N cos psi + c_E sin psi,
//            current_v = -c_N sin psi + c_E cos psi.
// Both come from the true motion, before the sensors' waves, noise and rates
// (sensors/sensor_chain.h), which then log them as they log the vessel's channels.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "effects/effect.h"
#include "effects/effect_values.h"
#include "simulation/wind_gusts.h"

namespace usvid {

// The names a suite's "logged" or `--logged` may hold.
const std::vector<std::string>& LoggableDisturbances();

// The channels that logging `disturbances` adds to a record, and that an equation method reads
// as inputs: wind_speed, wind_u, wind_v for the wind, current_u, current_v for the current.
std::vector<std::string> LoggedInputChannels(const std::vector<std::string>& disturbances);

// Checks `disturbances` against the conditions that make them: "wind" needs gusts, "current" a
// current among `effects`. InputError naming `where` and the item.
void CheckLoggedDisturbances(const std::vector<std::string>& disturbances, bool has_gusts,
                             const std::vector<Effect>& effects, const std::string& where);

// Adds the logged disturbances' channels to `data`, a vessel's true record (psi, u, v) made under
// `gusts` (null: none) seeded with `seed`, and `effects`, and returns their names. InputError if
// the record lacks psi, u or v.
std::vector<std::string> LogDisturbances(Dataset& data,
                                         const std::vector<std::string>& disturbances,
                                         const WindGusts* gusts, uint64_t seed,
                                         const EffectValues<double>& effects);

}  // namespace usvid
