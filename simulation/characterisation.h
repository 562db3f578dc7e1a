// What a simulator does in steady state, for docs, plots and sanity checks: the steady speed for
// each thrust command going straight, and the steady turn (speed, rate, radius U/|r|) at a yaw
// command. Each point is a run-in to steady state under a constant command (up to 1200 s).
#pragma once

#include <vector>

#include "simulation/vessel_simulator.h"

namespace usvid {

struct SteadyPoint {
  double thrust = 0.0;   // the thrust command
  double yaw = 0.0;      // the yaw command
  double speed = 0.0;    // steady speed over ground [m/s]
  double rate = 0.0;     // steady yaw rate [rad/s]
  double radius = 0.0;   // U / |r| [m], 0 when going straight
  bool settled = false;  // the run-in reached steady state before its limit
};

// `points` thrust commands evenly over the thrust input's range, at the given yaw command.
// Throws InputError when the vessel has no thrust input.
std::vector<SteadyPoint> SteadySweep(const VesselSimulator& sim, const std::vector<double>& params,
                                     int points, double yaw_command);

}  // namespace usvid
