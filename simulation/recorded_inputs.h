// The recorded commands of a data file as a zero-order-hold InputTrack, for replaying them on a
// vessel: one row per data row, an unsampled cell holding the input's last sample (its first
// sample before that). Throws InputError, naming the data's file, for a missing input column;
// a measured disturbance (the wind) the data lacks is held at its neutral value (none).
#pragma once

#include <array>
#include <optional>

#include "core/dataset.h"
#include "simulation/input_track.h"
#include "simulation/vessel_simulator.h"

namespace usvid {

InputTrack RecordedInputs(const Dataset& data, const VesselInfo& info);

// The air's velocity over the ground [north, east] on each row of `data`, from the relative wind
// it logs (wind_speed, wind_direction) and the hull's heading psi and velocities u, v
// (maneuvers/true_wind.h, AirOverGround): the relative wind aboard is the true wind seen from the
// logged hull, whose heading and velocities a free run or a replay does not share
// (docs/model.md#wind-on-its-own-heading). A row that lacks one of the five holds the last row's
// air (the first rows, the first air). Empty when the data lack one of them altogether, or their
// wind reads 0 throughout (no wind logged: a simulation without wind writes 0).
std::optional<std::array<Eigen::VectorXd, 2>> RecordedAirOverGround(const Dataset& data);

// `track`, RecordedInputs of `data`, with its measured wind turned into the air over the ground
// (RecordedAirOverGround), for a simulation that makes the relative wind from its own heading
// and velocities (EffectValues::wind_over_ground). Empty when the vessel reads no wind or the
// data cannot give the air.
std::optional<InputTrack> WindOverGround(const Dataset& data, const VesselInfo& info,
                                         const InputTrack& track);

}  // namespace usvid
