// `refit`: a registered vessel's own coefficients fitted to data with Ceres (for kvlcc2, the
// MMG hull derivatives of Yasukawa & Yoshimura 2015), the physics-based identification a naval
// architect starts from. Multiple shooting: the record is cut into segments of segment_s
// seconds, each simulated by the vessel's templated dynamics from its own initial state (free,
// estimated with the parameters); residuals are the simulated minus measured dynamic states
// (every state but north, east and the heading), each divided by its measurement noise (its sd
// estimated from the data, at least 0.1 % of the channel's spread), at every sample. The free
// parameters are fitted as ratios to their starting values, with a Gaussian prior of relative
// standard deviation prior_sd around the start (a coefficient the data cannot see stays at its
// published value instead of wandering). The model JSON it gives names the vessel and its
// parameters; `usvid evaluate` free-runs it with the vessel itself.
#pragma once

#include <string>
#include <vector>

#include "core/dataset.h"

namespace usvid {

struct RefitOptions {
  // Parameter names; empty: the vessel's kRefitParams, else its damping and resistance groups.
  std::vector<std::string> free;
  double segment_s = 0.0;  // 0: automatic (simulation/segment_length.h)
  double prior_sd = 0.5;   // relative to the starting value
  int max_iterations = 100;
  int threads = 1;
};

struct RefitResult {
  std::vector<std::string> names;         // every parameter of the vessel, in order
  std::vector<double> start, params, sd;  // sd: 0 where not free or not available
  std::vector<std::string> free, channels;
  bool covariance_ok = false;
  std::string termination;
  bool converged = false;
  double initial_cost = 0.0, final_cost = 0.0;
  int iterations = 0, segments = 0;
  double segment_s = 0.0;
  double seconds = 0.0;
};

// Throws InputError for an unknown vessel or parameter, or data without the vessel's inputs or
// dynamic states.
RefitResult RefitVessel(const std::string& vessel, const Dataset& data,
                        const std::vector<double>& start, const RefitOptions& options);

}  // namespace usvid
