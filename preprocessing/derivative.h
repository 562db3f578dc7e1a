// Smoothed signals and their time derivatives on a uniform grid, by a named method:
//   euler[:W]     the reference report's pipeline: Savitzky-Golay smoothing (W, order 2,
//                 default W = 11), then backward Euler differences (half a sample late).
//   sg[:W[:P]]    Savitzky-Golay derivative, centred, window W (default 21), order P (3).
//   spline[:L]    cubic smoothing spline; L = lambda, default chosen from the data.
//   tv[:A]        total-variation-regularised differentiation (Chartrand 2011); A = alpha,
//                 default chosen from the data.
// Where the inputs are piecewise constant the true derivative jumps at every step; given those
// samples as `breaks` (StepBreaks), `spline` fits each stretch between steps on its own, which
// removes the smoothing bias at the jumps. The other methods ignore breaks. The default,
// `spline` with the inputs' step breaks, is the most accurate over 0.1 % to 5 % noise on
// simulated maneuvers (docs/preprocessing.md).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace usvid {

struct DerivativeMethod {
  enum class Kind { kEuler, kSavitzkyGolay, kSpline, kTv };
  Kind kind = Kind::kSpline;
  int window = 21;
  int order = 3;
  double parameter = -1.0;  // lambda or alpha; <= 0: automatic

  // Throws InputError naming the spec, e.g. "--derivative 'sg:20:3': window must be odd".
  static DerivativeMethod Parse(const std::string& spec);
  std::string Spec() const;
};

struct SmoothedSignal {
  Eigen::VectorXd value;       // the smoothed signal
  Eigen::VectorXd derivative;  // its time derivative [units/s]
};

// y sampled every dt seconds (fully sampled: resample first).
SmoothedSignal SmoothAndDifferentiate(const Eigen::VectorXd& y, double dt,
                                      const DerivativeMethod& method,
                                      const std::vector<Eigen::Index>& breaks = {});

// The samples at which any input steps: changes by more than `fraction` of its range from the
// previous sample, where the samples before and after do not (a smooth input has none; one that
// ramps over several samples at its slew rate, none; a constant one, also one whose range is
// rounding, none). Shift inputs by a known delay first.
std::vector<Eigen::Index> StepBreaks(const std::vector<Eigen::VectorXd>& inputs,
                                     double fraction = 0.02);

}  // namespace usvid
