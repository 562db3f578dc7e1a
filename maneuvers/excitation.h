// The excitation ranges an open-loop maneuver uses per input role: thrust between 10 % and 100 %
// of its range (the throttle is varied, never held: the reference report's own lesson), yaw
// within +-yaw_full, side inputs within their range; fixed inputs at neutral.
#pragma once

#include <utility>

#include "maneuvers/maneuver.h"

namespace usvid {

// [low, high] of the command an excitation of input i moves between.
std::pair<double, double> ExcitationRange(const Actuation& act, int i);

// The vessel's neutral inputs with thrust at cruise: where open-loop maneuvers start.
std::vector<double> CruiseCommand(const Actuation& act);

}  // namespace usvid
