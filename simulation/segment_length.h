// How long a multiple-shooting segment should be for a vessel: long enough for the hull to
// respond (a segment much shorter than the response time shows the initial state, not the
// dynamics). 1.5 hull lengths of travel at the data's median speed, at least 10 s; 10 s for a
// model without a length. Used by diagnose and refit when no --segment is given; sindy's weak
// form takes its window from HullLengthSeconds.
#pragma once

#include "core/dataset.h"
#include "simulation/vessel_simulator.h"

namespace usvid {

double AutomaticSegmentSeconds(const Dataset& data, const VesselInfo& info);

// The time one hull length of travel takes at the data's median speed (from U, else u and v):
// the vessel's time scale L/U [s]. 0 for a model without a length or data without speed.
double HullLengthSeconds(const Dataset& data, const VesselInfo& info);

}  // namespace usvid
