// A maneuver's Fisher information for a method's parameters, before any data exist: the
// maneuver is simulated on the vessel (noise-free, nominal parameters), and the sensitivities of
// the method's normalised residuals to its parameters come from Jets through the templated
// simulator, the same multiple-shooting problem the method solves (design/method_problem.h,
// methods/refit with information_only). Under Gaussian measurement noise, the information is
// J^T J with the segments' initial states taken out. Its inverse bounds the covariance of any
// unbiased estimate of that problem (Cramer-Rao), and is the covariance of the shooting fits
// (refit, fossen-ceres: maximum likelihood). eb-lr uses a part of the record only; its own
// covariance is eb_lr_information.h's. The method's covariance gives
//  - the predicted standard deviation of each parameter (absolute, and relative to its value);
//  - log det (D-optimality: the volume of the confidence ellipsoid), the trace of the inverse
//    (A-optimality: the summed relative variances), and the condition number;
//  - the weakest directions: the eigenvectors of the smallest eigenvalues, in parameter names
//    (the combinations the maneuver cannot tell apart).
// All of it in units relative to the parameters' values, so maneuvers and parameters compare.
//
// Parameters of interest (DesignProblem::focus): the criteria are those of their information
// with the other parameters as nuisances, (C_FF)^-1 for C the covariance (Ds-optimality: a
// trial for the yaw damping need not pin the surge resistance). Every parameter's sd is still
// reported.
//
// The sensors are the same whatever the maneuver: each channel's noise sd is `noise` times its
// spread on a reference maneuver (the first one studied), not on the maneuver itself. (With the
// noise a fraction of each maneuver's own spread, as `usvid simulate --noise` makes it, a
// maneuver that barely moves the vessel would have barely any noise, and a 1 Hz multisine on
// odin3dof came out best while its fits scattered 4 times more than predicted.)
//
// Throws InputError: what MethodProblemOf refuses, a parameter of interest the method does not
// have, an unknown maneuver, a duration or noise that is not positive.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "simulation/vessel_ref.h"

namespace usvid::design {

// Measurement noise sd per state channel (absolute, in the channel's units).
using NoiseModel = std::map<std::string, double>;

// What a design study asks.
struct DesignProblem {
  VesselRef vessel;  // resolved where named
  std::string method;
  double seconds = 600.0;  // trial length
  NoiseModel noise;
  std::vector<std::string> focus;  // parameters of interest, as the method names them; empty: all
};

struct WeakDirection {
  double eigenvalue = 0.0;  // information along it (1 / relative variance)
  std::vector<std::pair<std::string, double>> parameters;  // unit vector, largest |weight| first
};

struct ManeuverInformation {
  std::string maneuver;
  std::vector<std::string> names;            // the method's free parameters, as it names them
  std::vector<double> values, sd, relative_sd;  // nominal value, predicted sd, sd / |value|
  // What an efficient multiple-shooting fit of the same model would reach on the trial: the sd
  // of refit's problem (segments' initial states estimated too). The same as sd for the
  // shooting fits (refit, fossen-ceres); beside eb-lr's own sd, what eb-lr leaves unused.
  std::vector<double> shooting_sd;
  Eigen::MatrixXd information;  // the method's, relative units, every free parameter
  // The criteria, over the parameters of interest (all, without a focus).
  double log_det = 0.0, trace_inverse = 0.0, condition_number = 0.0;
  std::vector<WeakDirection> weakest;  // the two smallest eigenvalues, smallest first
  // Why the method cannot fit this maneuver at all (design/method_problem.h); "" when it can.
  // An unusable maneuver is never the best, whatever its information.
  std::string unusable;
  double seconds = 0.0;
  std::string optimized_from;  // the family --optimize searched; "" for a maneuver as given
};

// Measurement noise sd per channel: `noise` x its spread on `reference`.
NoiseModel ReferenceNoise(const Dataset& reference, const std::vector<std::string>& channels,
                          double noise);

// Throws InputError for an unknown method, vessel or parameter of interest.
void CheckProblem(const DesignProblem& problem);

// The maneuver `spec` of `seconds` on the vessel, simulated once (seed: for random maneuvers).
Dataset SimulateManeuver(const VesselRef& vessel, const std::string& spec, double seconds,
                         uint64_t seed);

// The trial as a method would record it: the maneuver (its seed 1) with each channel's noise as
// the design assumed it, drawn from `noise_seed`.
Dataset NoisyRun(const DesignProblem& problem, const std::string& maneuver, uint64_t noise_seed);

ManeuverInformation InformationOf(const DesignProblem& problem, const std::string& maneuver,
                                  uint64_t seed = 1);

}  // namespace usvid::design
