// How a simulation runs: integration step, output (and control) rate, run-in to steady state.
#pragma once

#include "simulation/integrator.h"

namespace usvid {

struct RunOptions {
  double dt = 0.01;         // integration step [s]
  double rate_hz = 20.0;    // output rate, and the rate the maneuver's controller runs at
  double run_in_s = 600.0;  // longest run-in to steady state before t = 0
  Integrator integrator = Integrator::kRk4;
};

}  // namespace usvid
