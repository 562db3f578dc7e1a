// Maneuvers by name (docs/data.md#maneuvers): zigzag[:A/B] (default 20/20), turning[:A] (35),
// stepgrid[:T/Y[/H]] (4 thrust levels, 3 yaw levels a side; H a fixed hold per step [s]),
// random-steps[:HOLD_S] (6 s),
// prbs[:CLOCK_S] (4 s), multisine[:FMAX_HZ] (0.2 Hz), autopilot[:HOLD_S] (20 s; a heading
// autopilot's course changes, maneuvers/autopilot.h). duration_s = 0 takes the maneuver's
// default: 300 s for zig-zag and turning, 600 s for the random ones and the autopilot, up to
// 3600 s for the grid
// (it ends when the grid is done). Throws InputError naming the spec and what is wrong.
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

}  // namespace usvid
