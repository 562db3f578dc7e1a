// GP's chosen equations refitted by their simulation error (output error) rather than their
// equation error: the terms stay, and every equation's bias and weights are fitted together so
// that the model, integrated from the measured states over short segments of the record, follows
// the measured states. Least squares on the equation error fits derivative estimates: it weighs
// transients, where the derivative is large, over steady states, where it is small, so a model
// can be off in its steady speed by a share of the thrust-drag balance that a free run then
// integrates; and its noisy regressors bias products such as v*r toward zero (errors in
// variables). The simulation error is what a free run scores (docs/gp.md, "Simulation refit").
//
// Ceres's Levenberg-Marquardt with central differences through the segment simulator
// (segment_simulator.h): one residual per segment, step and state, the error over the state's
// standard deviation over the record. The weights are fitted on the record's first part (GP's
// search part) and kept only when they also lower the same error on the rest (the validation
// part, which they never saw) and the refitted model still free-runs the whole record within
// the bounds: weights fitted to one maneuver's simulation can follow it better and the next one
// worse, where the equation's terms are not the physics (a tanker's zig-zag, docs/gp.md). The
// check is conservative: the equation-error weights it compares with were fitted on every row,
// the validation part included. Kept weights are those fitted on the first part.
#pragma once

#include <string>
#include <vector>

#include "methods/gp/search.h"
#include "methods/gp/segment_simulator.h"

namespace usvid::gp {

struct SimulationRefitOptions {
  double horizon_s = 10.0;  // of each segment
  int max_iterations = 30;
  long fit_rows = 0;  // the weights are fitted on rows [0, fit_rows), checked on the rest
  // Most rows the fitted segments hold in all: on a long record the segments are spread evenly
  // over the fit part, so the dense Jacobian (rows x states x weights) stays bounded (a 2-hour
  // 50 Hz log's took 400 MB). 30000 rows are 25 minutes at 20 Hz: shorter records fit them all.
  long max_rows = 30000;
};

struct SimulationRefit {
  bool accepted = false;
  std::string reason;                             // why it was kept or not
  double initial_error = 0.0, final_error = 0.0;  // mean squared error over the variance
  double validation_error_before = 0.0, validation_error_after = 0.0;  // the same, the rest
  double free_run_error_before = 0.0, free_run_error_after = 0.0;      // the whole record
  int iterations = 0, segments = 0, validation_segments = 0, parameters = 0;
};

// `data`: every row (its validation_begin sets the rows the variances are taken over);
// `models[s]` is the equation of the variable state_vars[s]. On acceptance, the models' biases
// and weights are replaced. Not accepted when the fit part or the rest is shorter than a
// segment.
SimulationRefit RefitBySimulation(const SelectionData& data, const std::vector<int>& state_vars,
                                  std::vector<Model>& models,
                                  const SimulationRefitOptions& options);

}  // namespace usvid::gp
