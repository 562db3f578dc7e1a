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
//
// Missing terms (effects/effect.h, `missing_term`) may be fitted with the parameters: each adds
// coefficient * term(x, u) to its state's derivative, the coefficient free (no prior) from its
// given value; at most kMaxRefitTerms. The hybrid method (methods/hybrid) finds them.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/dataset.h"
#include "effects/effect.h"
#include "simulation/vessel_ref.h"

namespace usvid {

// The name --method and suites give it (methods/method_list.h registers it).
inline constexpr std::string_view kRefitMethodName = "refit";

struct RefitOptions {
  // Parameter names; empty: the vessel's kRefitParams, else its damping and resistance groups.
  std::vector<std::string> free;
  double segment_s = 0.0;  // 0: automatic (simulation/segment_length.h)
  double prior_sd = 0.5;   // relative to the starting value
  // Most rows the segments hold (0: all): on a longer record, segments spread evenly over it
  // (Ceres holds the Jacobian of every residual).
  long max_rows = 0;
  // Each record of a joint fit (core/records.h) weighs the same, whatever its length
  // (record_weights.h); false: each segment does, so a record weighs by its rows.
  bool equal_records = false;
  int max_iterations = 100;
  // Ceres stops when a step lowers the cost by less than this share of it. Over the 27 folds of
  // Esso Osaka's cross-validated refit, 1e-10 let eight run to max_iterations crawling along a
  // valley (the last 56 steps of one lowered the cost by 2e-5 of itself in all); 1e-6 stopped
  // five of them at 21-95 iterations, each fold's cost within 8e-4 of its value at 1e-10
  // (docs/performance.md#what-profiling-found-and-what-was-done-about-it, item 8). Not used with
  // hold_model, whose scores keep 1e-10 (SolveRefit, typed_refit.h).
  double function_tolerance = 1e-6;
  int threads = 1;
  std::vector<Effect> terms;  // missing_term effects, their coefficients fitted
  // Only each segment's initial state is fitted, the parameters and terms held: the record's
  // multiple-shooting error under a given model (a held-out score).
  bool hold_model = false;
  // Each named channel's measurement noise sd, instead of estimated from the data (a design
  // study's sensors).
  std::map<std::string, double> noise_sd;
  // No fit: the Fisher information of the free parameters at the start (a design study,
  // design/). The segments' initial states are nuisances: their information is taken out (the
  // Schur complement of JᵀJ, J the Jacobian of the normalised residuals, the prior's included).
  bool information_only = false;
};

constexpr int kMaxRefitTerms = 6;

struct RefitResult {
  std::vector<std::string> names;         // every parameter of the vessel, in order
  std::vector<double> start, params, sd;  // sd: 0 where not free or not available
  std::vector<std::string> free, channels;
  std::vector<Effect> terms;  // the options' terms with their fitted coefficients
  bool covariance_ok = false;
  std::string termination;
  bool converged = false;
  double initial_cost = 0.0, final_cost = 0.0;
  int iterations = 0, segments = 0, residuals = 0;
  double segment_s = 0.0;
  double seconds = 0.0;
  // With hold_model: the integrated autocorrelation time of the residuals [samples], 1 + 2 sum
  // rho_k over the lags before rho first drops below 0.05 (at most 400), averaged over the
  // channels: the residuals carry about residuals / correlation_time independent ones.
  double correlation_time = 1.0;
  // With information_only: the Fisher information of the free parameters (in free's order), in
  // units of their ratio to the start (1 / relative variance).
  Eigen::MatrixXd information;
};

// Throws InputError for an unknown vessel or parameter, or data without the vessel's inputs or
// dynamic states.
RefitResult RefitVessel(const VesselRef& vessel, const Dataset& data,
                        const std::vector<double>& start, const RefitOptions& options);

// The mean squared normalised residual of a fit: 2 final_cost / residuals (the prior's part is
// included; 0 with the parameters held).
double MeanSquaredError(const RefitResult& fit);

// What the vessel with `params` leaves unexplained in each dynamic state's derivative:
//   d_s = s_dot - f_s(x, u; params)
// at every row of preprocessed data (smoothed states and inputs, derivatives "<s>_dot"; the
// kinematic states from the data where present, else 0). Throws InputError for an unknown
// vessel or a missing channel.
std::map<std::string, Eigen::VectorXd> DerivativeResidual(const VesselRef& vessel,
                                                          const Dataset& prepared,
                                                          const std::vector<double>& params);

}  // namespace usvid
