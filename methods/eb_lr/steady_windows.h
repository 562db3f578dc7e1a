// Steady-state windows of a step experiment, found from the data alone (method eb-lr, step 1).
// The record is cut at every input step: a sample where some input changes by more than
// input_tolerance x its range over the record (StepBreaks). Inside each stretch, sample k is
// settled when, for every state x, the least-squares slope x'_k over slope_window_s seconds
// (clipped to the stretch) obeys
//     |x'_k| <= noise_factor sd(x'_k) + max_relative_rate (|x_k| + scale_floor max|x|),
// where sd(x'_k) = sd(x) / sqrt(sum (t - t_mean)^2) is the slope's standard deviation under
// white noise of sd(x), estimated from the record (EstimateNoiseSd): a slope within the noise,
// or slower than max_relative_rate of the state's size per second. The stretch's last run of
// settled samples lasting at least min_window_s, over which no input spreads by more than
// input_tolerance x its range, is its steady window; a stretch has at most one.
// A stretch with no such run whose rate state (full_turn_state) turns the heading through a full
// circle or more is steady on average over its last full turn (Eriksen & Breivik's full turn,
// which averages out the wind and the current that keep a real turn from settling): that last
// turn is its window, when the stretch holds at least 1.25 turns (the first quarter for the
// transient) and no input drifts over it.
// Units: t [s], states and inputs in their own units, rates per second.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace usvid::eb_lr {

struct SteadyWindowOptions {
  double input_tolerance = 0.005;    // [-] of each input's range: a larger change is a step
  double slope_window_s = 2.0;       // [s] local least-squares slope
  double noise_factor = 4.0;         // [-] slopes within this many standard deviations of 0
  double max_relative_rate = 0.002;  // [1/s] or slower than this fraction of |x| per second
  double scale_floor = 0.1;          // [-] |x| taken at least this fraction of max|x|
  double min_window_s = 3.0;         // [s] shortest steady window
  int full_turn_state = -1;          // the rate state [rad/s] whose full turns count; -1: none
};

struct SteadyWindow {
  Eigen::Index first = 0, last = 0;  // sample indices, inclusive
};

struct SteadyWindowReport {
  std::vector<SteadyWindow> windows;  // in time order
  std::vector<double> noise_sd;       // per state
  int stretches = 0;                  // stretches of constant input
  int drifting = 0;                   // settled runs refused because an input drifted
  int full_turns = 0;                 // windows that are a stretch's last full turn
};

// t strictly increasing; every state and input as long as t. `joins`: the first samples of the
// record's later stretches (records joined, gaps), where the record is cut too; the grid's step
// is then the median interval. Throws InputError on a bad option (named) or mismatched lengths.
SteadyWindowReport DetectSteadyWindows(const Eigen::VectorXd& t,
                                       const std::vector<Eigen::VectorXd>& states,
                                       const std::vector<Eigen::VectorXd>& inputs,
                                       const SteadyWindowOptions& options,
                                       const std::vector<Eigen::Index>& joins = {});

}  // namespace usvid::eb_lr
