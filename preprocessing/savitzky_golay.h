// Savitzky-Golay smoothing and differentiation on a uniform grid: at each sample a polynomial
// of degree `order` is fitted by least squares to the `window` samples centred on it, and its
// value or derivative there is the estimate. Centred windows make it zero-phase (no lag); at
// the ends the window is shifted inwards and the polynomial evaluated off-centre.
// Throws InputError when window is even, < order + 2, or longer than the signal, or dt <= 0.
#pragma once

#include <Eigen/Core>

namespace usvid {

struct SavitzkyGolay {
  int window = 21;  // odd number of samples
  int order = 3;    // polynomial degree

  // The derivative'th derivative (0: smoothing) of y sampled every dt seconds.
  Eigen::VectorXd Apply(const Eigen::VectorXd& y, double dt, int derivative) const;

  // Weights w with estimate = sum_k w_k y_{start + k}, for a window whose first sample is
  // `position` samples before the evaluation point (window / 2 for the centred case).
  Eigen::VectorXd Weights(int position, int derivative, double dt) const;
};

}  // namespace usvid
