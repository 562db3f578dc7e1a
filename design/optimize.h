// --optimize: a maneuver family's knobs searched for the largest log det of the information
// (D-optimal design), by NLopt's DIRECT-L (global, derivative-free, deterministic) within
// bounds, at the trial length given:
//   zigzag:A/B      rudder angle A in [5, the vessel's full rudder], heading B in [5, 40] deg
//   random-steps:H  hold time H in [1, 60] s
//   prbs:C          clock period C in [0.5, 30] s
//   multisine:F     top frequency F in [0.02, 1] Hz
//   stepgrid:T/Y    thrust levels T in [2, 8], yaw levels Y (each side) in [1, 5], whole numbers
// The levels and amplitudes are the maneuvers' own (they already span the actuators' range).
// turning has no knob searched. A design the method cannot fit (eb-lr without
// steady windows) or that cannot be simulated scores nothing: the search stays where the method
// works. The best point is written as a spec with three
// significant digits and evaluated again as written, so the design reported is the one a person
// can run.
#pragma once

#include <optional>
#include <string>

#include "design/information.h"

namespace usvid::design {

// nullopt for a family without knobs (turning).
std::optional<ManeuverInformation> OptimizeManeuver(const DesignProblem& problem,
                                                    const std::string& family,
                                                    int evaluations = 40);

}  // namespace usvid::design
