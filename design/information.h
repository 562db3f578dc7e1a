// A maneuver's Fisher information for a method's parameters, before any data exist: the
// maneuver is simulated on the vessel (noise-free, nominal parameters), and the sensitivities of
// the method's normalised residuals to its parameters come from Jets through the templated
// simulator, the same multiple-shooting problem the method solves (methods/refit with
// information_only). Under Gaussian measurement noise, the information is J^T J with the
// segments' initial states taken out. Its inverse bounds the covariance of any unbiased
// estimate (Cramer-Rao); it gives
//  - the predicted standard deviation of each parameter (absolute, and relative to its value);
//  - log det (D-optimality: the volume of the confidence ellipsoid), the trace of the inverse
//    (A-optimality: the summed relative variances), and the condition number;
//  - the weakest directions: the eigenvectors of the smallest eigenvalues, in parameter names
//    (the combinations the maneuver cannot tell apart).
// All of it in units relative to the parameters' values, so maneuvers and parameters compare.
//
// The sensors are the same whatever the maneuver: each channel's noise sd is `noise` times its
// spread on a reference maneuver (the first one studied), not on the maneuver itself. (With the
// noise a fraction of each maneuver's own spread, as `usvid simulate --noise` makes it, a
// maneuver that barely moves the vessel would have barely any noise, and a 1 Hz multisine on
// odin3dof came out best while its fits scattered 4 times more than predicted.)
//
// Methods: refit (the vessel's own free coefficients, with refit's prior) and fossen-ceres on
// odin3dof (its model is odin3dof's 10 parameters, no prior, 10 s segments). Throws InputError
// for another method (gp and sindy have no parameters), another vessel for fossen-ceres, an
// unknown maneuver, or a duration that is not positive.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "methods/refit/refit.h"

namespace usvid::design {

struct WeakDirection {
  double eigenvalue = 0.0;  // information along it (1 / relative variance)
  std::vector<std::pair<std::string, double>> parameters;  // unit vector, largest |weight| first
};

struct ManeuverInformation {
  std::string maneuver;
  std::vector<std::string> names;            // the method's free parameters
  std::vector<double> values, sd, relative_sd;  // nominal value, predicted sd, sd / |value|
  Eigen::MatrixXd information;               // relative units
  double log_det = 0.0, trace_inverse = 0.0, condition_number = 0.0;
  std::vector<WeakDirection> weakest;  // the two smallest eigenvalues, smallest first
  double seconds = 0.0;
  std::string optimized_from;  // the family --optimize searched; "" for a maneuver as given
};

// Measurement noise sd per state channel: `noise` x its spread on `reference`.
using NoiseModel = std::map<std::string, double>;
NoiseModel ReferenceNoise(const Dataset& reference, const std::vector<std::string>& channels,
                          double noise);

// What the method fits on the vessel: its free parameters, prior and segments.
RefitOptions MethodProblem(const std::string& vessel, const std::string& method);

// The maneuver `spec` of `seconds` on the vessel, simulated once (seed: for random maneuvers).
Dataset SimulateManeuver(const std::string& vessel, const std::string& spec, double seconds,
                         uint64_t seed);

ManeuverInformation InformationOf(const std::string& vessel, const std::string& method,
                                  const std::string& maneuver, double seconds,
                                  const NoiseModel& noise, uint64_t seed = 1);

}  // namespace usvid::design
