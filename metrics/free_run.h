// Free-run (simulation) of a model written as equations (model.json): the identified states
// integrated by RK4 from the data's first row under the data's inputs (zero-order hold, shifted
// by the model's input delay), with the known kinematics for the states that have no equation:
//   body velocities u, v, r:  psi' = r, north' = u cos psi - v sin psi, east' = u sin psi + v cos
//   psi speed and turn U, r:      chi' = r, north' = U cos chi, east' = U sin chi msd velocity v:
//   x' = v;  a rate of turn r alone (a heading model): psi' = r
// A model without equations that names a registered vessel (a vessel model: {"vessel": "kvlcc2",
// "parameters": {...}, "effects": [...]}, as `identify --method refit` and `diagnose` write them,
// or just {"vessel": "kvlcc2"} for the nominal simulator) is free-run by that simulator on the
// data's inputs from the data's first row, its measured states compared.
// The run stops when a state leaves its bound (ten times the data's largest magnitude, at least
// 1e3): it is then reported as diverged and the rest holds the last finite value, so scores stay
// finite.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/dataset.h"

namespace usvid {

struct FreeRun {
  Dataset simulated;                  // the integrated channels at the data's time stamps
  std::vector<std::string> channels;  // what was integrated
  bool diverged = false;
  double diverged_at_s = 0.0;
};

// Throws InputError for a model without equations, an equation that does not parse, or a
// channel the data lack.
FreeRun FreeRunModel(const nlohmann::json& model, const Dataset& data, double max_step = 0.01);

}  // namespace usvid
