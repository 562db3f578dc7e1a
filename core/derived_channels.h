// Channels derived from logged ones, added where they are missing so that a model may name them
// (docs/data.md#derived-channels):
// - speed over ground and course from body velocities, for data that have u, v and psi but not
//   U and chi (odin3dof logs; the 2-DOF models need them):
//     U = sqrt(u^2 + v^2),   chi = psi + atan2(v, u);
// - the relative wind's body components from its speed and direction (where it blows from,
//   clockwise from the bow; docs/model.md#wind), the air's velocity past the ship:
//     wind_u = -wind_speed cos(wind_direction),   wind_v = -wind_speed sin(wind_direction).
//   A head wind has wind_u < 0, a wind from starboard wind_v < 0. The wind's pressure force is
//   a product of two of wind_speed, wind_u and wind_v (V^2 cos gamma = -V wind_u, V^2 sin 2 gamma
//   = 2 wind_u wind_v), so the equation methods can build it from their products.
// A row is sampled where every channel it is derived from is.
#pragma once

#include <string>

#include "core/dataset.h"

namespace usvid {

void AddSpeedAndCourse(Dataset& data);
void AddWindComponents(Dataset& data);

// Both of the above: what identification, evaluation and replay add before they read a model's
// channels.
void AddDerivedChannels(Dataset& data);

// Whether AddDerivedChannels would give `data` the channel `name` (it has what it is derived
// from): a command that checks its records' channels before it identifies accepts these.
bool CanDerive(const Dataset& data, const std::string& name);

// What a derived channel is derived from, for an error that names it ("wind_speed and
// wind_direction"); empty for a channel that is not derived.
std::string DerivedFrom(const std::string& name);

}  // namespace usvid
