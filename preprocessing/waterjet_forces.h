// The forces of Odin's two waterjets from their measured states, as input channels that any
// method can use in place of the commands (`--forces waterjet`):
//   per jet  Q = jet_flow_per_rpm rpm [m^3/s],  V_j = Q / nozzle_area [m/s],
//            g(b) = b ((1 + eta) + (1 - eta) tanh(b / 0.05)) / 2  (1 ahead, -eta astern),
//   tau_x = 2 rho Q g(b) V_j cos(delta)  [N],  tau_y = -2 rho Q V_j sin(delta)  [N],
//   tau_n = x_j tau_y  [N m]  (the jets at x_j = -3.82 m, side by side: their surge moments
//   cancel),  jet_flow = 2 Q  [m^3/s].
// This is the jets' momentum thrust, what the commands cannot give: thrust goes with rpm^2, its
// direction with the nozzle angle, and the commands reach the jets through a transport delay and
// slew-limited actuators. The inlet momentum (-rho Q ((1 - w) u_r, v_r + x_j r) per jet) depends
// on the velocities and is left to the hull model, which jet_flow lets it write (Q u, Q v, Q r).
// Parameters: odin-hs's (simulators/odin_hs.h, docs/vessels/odin-hs.md).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/dataset.h"

namespace usvid {

// The channels the map reads: shaft speed [rev/min], nozzle angle [rad], bucket [-1, 1].
inline const std::array<std::string, 3> kWaterjetStateChannels = {"rpm", "nozzle_angle",
                                                                  "bucket_position"};
// The channels it writes.
inline const std::array<std::string, 4> kWaterjetForceChannels = {"tau_x", "tau_y", "tau_n",
                                                                  "jet_flow"};

// Whether `channels` (a vessel's states, a log's columns) hold every jet state: a waterjet craft.
bool HasWaterjetStates(const std::vector<std::string>& channels);

// tau_x, tau_y, tau_n, jet_flow (kWaterjetForceChannels' order) of one sample of the jet states.
std::array<double, 4> WaterjetForces(double rpm, double nozzle_angle, double bucket_position);

// Adds tau_x, tau_y, tau_n, jet_flow, sampled where all three jet states are. Throws InputError
// naming the jet-state channels the data lack, or a force channel the data already have.
void AddWaterjetForces(Dataset& data);

// The input map `--forces` names: "" adds nothing, "waterjet" is AddWaterjetForces. Throws
// InputError for another name.
void AddForces(Dataset& data, const std::string& map);
// The channels the map `map` writes (empty for ""); throws InputError as AddForces.
std::vector<std::string> ForceChannels(const std::string& map);

}  // namespace usvid
