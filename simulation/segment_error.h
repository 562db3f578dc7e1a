// How far a simulator's free run is from measured data, over short segments: the data are cut
// into segments of segment_s seconds, each simulated open-loop from its first row's measured
// state under the recorded inputs, and the squared errors of the state channels, each divided by
// that channel's variance over the data, are averaged. Short segments keep the cost smooth for
// unstable hulls, whose long free runs separate whatever the parameters. A diverged segment
// costs as much as predicting zero.
#pragma once

#include <string>
#include <vector>

#include "simulation/vessel_simulator.h"

namespace usvid {

double SegmentedSimulationError(const VesselSimulator& sim, const std::vector<double>& params,
                                const EffectValues<double>& effects, const Dataset& data,
                                const std::vector<std::string>& channels, double segment_s,
                                const RunOptions& options = {});

}  // namespace usvid
