// The preprocessing every derivative-based identification runs, in one call: multi-rate data
// onto a uniform grid, the input delay (given, or estimated by the equation-error scan) taken
// out by shifting the inputs, then each state smoothed and differentiated (by default with
// breaks where the shifted inputs step). A record with gaps, or records joined for one fit
// (core/records.h), is processed one stretch between gaps at a time (core/stretches.h): no
// derivative or shifted input crosses a gap, and the grid keeps it. Used by `usvid preprocess`
// and `usvid identify`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "preprocessing/delay_estimation.h"
#include "preprocessing/derivative.h"
#include "preprocessing/resample.h"

namespace usvid {

struct PreprocessOptions {
  double rate_hz = 0.0;  // 0: the data's own rate (median interval)
  Interpolation interpolation = Interpolation::kCubicSpline;
  DerivativeMethod derivative;
  // The spline's breaks at the inputs' steps (derivative.h), where the inputs are piecewise
  // constant. Where half the record lies in stretches between breaks shorter than min_piece_s,
  // the "steps" are a quantised, noisy or hand-moved input's (a real log's rpm and rudder), the
  // stretches too short to differentiate, and none are used (said in the notes).
  bool step_breaks = true;
  double min_piece_s = 1.5;
  // Delay in seconds, or none: estimated when `estimate_delay`.
  double delay_s = 0.0;
  bool estimate_delay = false;
  double max_delay_s = 2.0;
  // "waterjet": the jets' forces added from their states before anything else
  // (waterjet_forces.h); empty: none. Applied by the callers that read the raw record
  // (identify, preprocess, evaluate), not by Preprocess().
  std::string forces;
};

struct PreparedData {
  // The grid: states (smoothed), "<state>_dot" derivatives, inputs shifted by the delay, and
  // the raw (resampled) states as "<state>_raw".
  Dataset data;
  double delay_s = 0.0;
  std::optional<DelayEstimate> delay_estimate;
  std::vector<std::string> notes;  // what was done, for stderr and model.json
};

// Throws InputError naming a missing channel or a bad option.
PreparedData Preprocess(const Dataset& data, const std::vector<std::string>& states,
                        const std::vector<std::string>& inputs, const PreprocessOptions& options);

}  // namespace usvid
