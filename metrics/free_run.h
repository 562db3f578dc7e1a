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
// The run stops when a state leaves its bound (simulation/divergence_bounds.h): it is then reported
// as diverged, with the channel and time, and the rest holds the last finite value, so scores stay
// finite.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "effects/effect.h"
#include "simulation/divergence_bounds.h"

namespace usvid {

class VesselSimulator;

// A model without equations that names a registered vessel: its simulator, parameters (the
// vessel's defaults where the model names none) and effects.
struct VesselModel {
  const VesselSimulator* simulator = nullptr;
  std::vector<double> params;
  std::vector<Effect> effects;
};
bool IsVesselModel(const nlohmann::json& model);
// Throws InputError for an unknown vessel, parameter or effect.
VesselModel ParseVesselModel(const nlohmann::json& model);

struct FreeRun {
  Dataset simulated;                  // the integrated channels at the data's time stamps
  std::vector<std::string> channels;  // what was integrated
  bool diverged = false;
  double diverged_at_s = 0.0;
  std::string diverged_channel;  // the channel that left its bound
};

// Throws InputError for a model without equations, an equation that does not parse, or a
// channel the data lack.
FreeRun FreeRunModel(const nlohmann::json& model, const Dataset& data, double max_step = 0.01);

// Free runs over consecutive windows of `data`, each from its own first row, stitched into one
// record: window j holds the rows [starts[j], starts[j + 1]) (the last to the record's end) and
// is what FreeRunModel(model, data.Rows(...)) gives for it, bit for bit (its bounds are the
// window's, and a run that diverges holds its last value to the window's end). An equation
// model's windows are integrated side by side, each operator dispatched once per step for all
// of them; a vessel model's one after another. `diverged` says whether any window diverged.
// `starts` begins at 0 and ascends. Throws as FreeRunModel does.
FreeRun FreeRunWindows(const nlohmann::json& model, const Dataset& data,
                       const std::vector<Eigen::Index>& starts, double max_step = 0.01);

}  // namespace usvid
