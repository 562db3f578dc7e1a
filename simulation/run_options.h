// How a simulation runs: integration step, output (and control) rate, run-in to steady state.
#pragma once

#include <array>
#include <functional>
#include <span>
#include <vector>

#include "simulation/integrator.h"

namespace usvid {

struct RunOptions {
  double dt = 0.01;         // integration step [s]
  double rate_hz = 20.0;    // output rate, and the rate the maneuver's controller runs at
  double run_in_s = 600.0;  // longest run-in to steady state before t = 0
  Integrator integrator = Integrator::kRk4;
  // Closed-loop maneuvers: the state at t = 0, one value per state; NaN keeps the run-in's
  // steady value (empty: all of them). Positions and heading start at 0 regardless.
  std::vector<double> initial_state;
  // Closed-loop maneuvers: an unmeasured disturbance (simulation/wind_gusts.h), asked at every
  // control period for the accelerations [surge, sway, yaw rate] it gives the vessel in its
  // state at time t, held until the next period on top of the effects' own. Empty: none.
  std::function<std::array<double, 3>(double t, std::span<const double> state)> disturbance;
};

}  // namespace usvid
