// How far a simulator's free run is from measured data, over short segments: the data are cut
// into segments of segment_s seconds (none across a gap: a join of records, a dropout), each
// simulated open-loop from its first row's measured state under the recorded inputs, and the
// squared errors of the state channels, each divided by that channel's variance over the data,
// are averaged over the rows where the channel was sampled. Short segments keep the cost smooth
// for unstable hulls, whose long free runs separate whatever the parameters. A diverged segment
// costs as much as predicting zero. segment_s may be infinite: each stretch between gaps is one
// free run (the hybrid's check of its terms, methods/hybrid/heldout_free_run.h).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "simulation/vessel_simulator.h"

namespace usvid {

struct SegmentedError {
  double error = 0.0;
  // Whether a segment's run stopped early or left the bounds of simulation/divergence_bounds.h.
  bool diverged = false;
  // Whether the segments were left unrun at a SegmentStop: `error` is then what the segments
  // run so far add over all rows, a lower bound of the whole.
  bool stopped = false;
  // Each segment's share of `error` (its squared errors over the variances, over all rows' count),
  // in the data's order; NaN for a segment left unrun.
  std::vector<double> segment_errors;
};

// When a caller that needs only a bound may leave the remaining segments unrun: at the first
// that diverges, and once the error is sure to exceed `above` (the squared errors only add).
// `likely_errors` (one per segment, or empty) guesses each segment's error, say a similar model's
// segment_errors: the segments are then run largest guess first, so that a model worse than the
// bound is found out after fewer of them. A run that finishes has the same error, bit for bit, in
// any order (the squared errors are summed in the data's order).
struct SegmentStop {
  bool at_divergence = false;
  double above = std::numeric_limits<double>::infinity();
  std::vector<double> likely_errors;
};

SegmentedError SegmentedSimulationErrorOf(const VesselSimulator& sim,
                                          const std::vector<double>& params,
                                          const EffectValues<double>& effects, const Dataset& data,
                                          const std::vector<std::string>& channels,
                                          double segment_s, const RunOptions& options = {},
                                          const SegmentStop& stop = {});

// The error alone.
double SegmentedSimulationError(const VesselSimulator& sim, const std::vector<double>& params,
                                const EffectValues<double>& effects, const Dataset& data,
                                const std::vector<std::string>& channels, double segment_s,
                                const RunOptions& options = {});

}  // namespace usvid
