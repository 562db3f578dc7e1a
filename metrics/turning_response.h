// The turning-circle test's figures of merit (ITTC 7.5-04-02-01, IMO MSC.137(76)) read from any
// record, measured or simulated.
//
// Execute: where the first full-angle order held until the heading has turned 90 deg begins
// to move (metrics/maneuver_execute.h: a real log's hand steering before the test is skipped),
// else the first sample where the yaw command has moved from its initial value; moved means by
// more than 1 deg (0.01745) when it is an angle [rad], or by more than 1 % of its largest
// absolute value when it is a yaw moment or force; the channel counts as an angle when its largest
// absolute value is at most pi/2 (no rudder or nozzle goes further). The origin (n0, e0) and the
// initial heading psi0 are read there. The direction s is +1 to starboard (the heading grows), -1
// to port, read from the heading's largest excursion after the execute (0 if it never changes), so
// either rudder sign convention works. With turned = s (psi - psi0) and dn, de from the origin:
//   advance  =      dn cos psi0 + de sin psi0    at turned = 90 deg   [m]
//   transfer = s (-dn sin psi0 + de cos psi0)   at turned = 90 deg   [m] (to the turning side)
//   tactical diameter = transfer                 at turned = 180 deg  [m]
// each interpolated linearly in time between the samples around the crossing. Steady turn, over
// the last full 360 deg of the record (from turned_end - 360 deg to the last sample; it needs
// turned_end >= 540 deg, i.e. 360 deg turned after 180): rate = 360 deg / the time it took (the
// heading's slope, mean |r|), radius = the least-squares circle through the positions there
// (U / r on a steady turn in calm water).
//
// The heading is in radians; one that wraps at +-pi, as logs write it, is unwrapped first
// (core/angles.h). Noisy heading and positions are smoothed (metrics/criteria_smoothing.h).
// Unsampled values (NaN) are skipped: each channel is interpolated over its own samples.
#pragma once

#include <string>

#include "core/dataset.h"

namespace usvid {

struct TurningResponse {
  double execute_s = 0.0;  // time of the rudder execution
  int direction = 0;       // +1 starboard (heading grows), -1 port
  double advance_m = 0.0, transfer_m = 0.0, tactical_diameter_m = 0.0;  // NaN when not reached
  // Mean |r| over the last full 360 deg of turn [deg/s] and the radius of the circle sailed
  // there [m]; NaN if fewer than 360 deg were turned after 180.
  double steady_rate_deg_s = 0.0;
  double steady_radius_m = 0.0;
  bool reached_90 = false, reached_180 = false;
};

// Not reaching 90 or 180 deg is a result (flags false, values NaN). Throws InputError (naming
// the data's file) when a channel is missing or the rudder never moves.
// `find_execute` false: the execute is the first movement (a simulated run, which starts at its
// lead-in). `rudder_deg`: the test's rudder angle A of turning:A, the order the execute is found
// at (metrics/maneuver_execute.h); 0 takes the command's largest, which an operator's swing
// past A before the order (the Esso Osaka circle of 14 Oct 14:29: -24 deg, then 19.5) exceeds.
TurningResponse AnalyseTurning(const Dataset& data, const std::string& heading = "psi",
                               const std::string& rudder = "delta",
                               const std::string& north = "north", const std::string& east = "east",
                               bool find_execute = true, double rudder_deg = 0.0);

}  // namespace usvid
