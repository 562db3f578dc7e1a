// The recorded commands of a data file as a zero-order-hold InputTrack, for replaying them on a
// vessel: one row per data row, an unsampled cell holding the input's last sample (its first
// sample before that). Throws InputError, naming the data's file, for a missing input column;
// a measured disturbance (the wind) the data lacks is held at its neutral value (none).
#pragma once

#include "core/dataset.h"
#include "simulation/input_track.h"
#include "simulation/vessel_simulator.h"

namespace usvid {

InputTrack RecordedInputs(const Dataset& data, const VesselInfo& info);

}  // namespace usvid
