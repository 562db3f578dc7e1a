// Maneuvers by name (docs/data.md#maneuvers), one row each in the factory's table of forms
// (maneuver_factory.cc): its name and numbers as a user writes them (ManeuverGrammar) and how
// the numbers make it. duration_s = 0 takes the maneuver's default: 300 s for zig-zag and
// turning, 600 s for the random ones and the autopilot, up to 3600 s for the grid (it ends when
// the grid is done). Throws InputError naming the spec and what is wrong.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "maneuvers/maneuver.h"
#include "maneuvers/maneuver_spec.h"

namespace usvid {

std::unique_ptr<Maneuver> MakeManeuver(const std::string& spec, const Actuation& act,
                                       double duration_s, uint64_t seed);
// The same from a parsed spec (maneuvers/maneuver_spec.h), a zig-zag about its base course.
std::unique_ptr<Maneuver> MakeManeuver(const ManeuverSpec& spec, const Actuation& act,
                                       double duration_s, uint64_t seed);

// Every maneuver's name and numbers as a user writes them, "zigzag[:A/B], turning[:A], ...",
// for help texts and messages.
std::string ManeuverGrammar();

}  // namespace usvid
