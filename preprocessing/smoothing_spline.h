// Cubic smoothing spline on a uniform grid, with its first derivative (Reinsch 1967; Green &
// Silverman 1994, ch. 2). For samples y_i at t_i = i dt the fit f minimises
//     sum_i (y_i - f(t_i))^2 + lambda * integral f''(t)^2 dt,
// and is the natural cubic spline with a knot at every sample. With g_i = f(t_i), gamma_i =
// f''(t_i) (zero at both ends), Q the n x (n-2) second-difference matrix (1, -2, 1) / dt and
// R = dt tridiag(1/6, 2/3, 1/6),
//     (R + lambda Q^T Q) gamma = Q^T y,   g = y - lambda Q gamma,
// a pentadiagonal system solved by a banded LDL^T in O(n) time and memory. The derivative is
// the spline's own at the knots (not a finite difference):
//     f'(t_i) = (g_{i+1} - g_i) / dt - dt (2 gamma_i + gamma_{i+1}) / 6.
// The smoother is symmetric, so there is no lag; near the ends the natural condition f'' = 0
// biases the derivative over about one smoothing length.
//
// Units: value in y's units, derivative in y's units per second, dt in s, lambda in s^3. The
// dimensionless mu = lambda / dt^3 sets the bandwidth: in the interior a sinusoid of w rad per
// sample is scaled by r / (r + mu d^2), r = (2 + cos w) / 3, d = 2 - 2 cos w, so the spline
// passes w below about mu^(-1/4) and removes those above. Rounding grows with mu (the penalty's
// differences cancel): about 1e-9 of the signal at mu = 1e8, 4e-6 at 1e12, 2e-3 at 1e13. The
// least-squares line of y, which the penalty ignores, is removed first and added back.
//
// Automatic lambda (lambda <= 0): the noise standard deviation sd is estimated from the data
// (EstimateNoiseSd) and lambda minimises Mallows' C_L, RSS + 2 sd^2 tr H (H the hat matrix,
// g = H y), an unbiased estimate of n times the fitted values' mean squared error, less a
// constant. tr H comes from the band of the inverse of the factored system (Hutchinson & de Hoog
// 1985), so each trial costs O(n); mu is searched on a grid of decades over [1e-8, 1e12], then by
// golden section: about 36 trials, ~1 us per sample in all.
// Why C_L: on responses to piecewise-constant inputs (derivative jumps) with 0.1-5 % noise, its
// derivative error was within 3 % of the best lambda's, where the discrepancy principle (RMS
// residual = sd) oversmoothed by a factor 2-6 in lambda, for 5-17 % more error. GCV chose nearly
// the same lambda as C_L; C_L reuses the robust sd and so needs no special case without noise
// (sd = 0 gives the interpolating spline). On very smooth signals (sums of sines) C_L, which
// targets the values, undersmooths the derivative: 1.2-2x the best lambda's error.
//
// Throws InputError when dt is not positive and finite, y has fewer than 4 samples, a sample is
// not finite, lambda is NaN or +infinity, or lambda / dt^3 overflows.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace usvid {

struct SmoothingSplineResult {
  Eigen::VectorXd value;       // smoothed signal at the samples
  Eigen::VectorXd derivative;  // its first time derivative at the samples [units/s]
  double lambda = 0.0;         // the smoothing parameter used [s^3]
  double noise_sd = 0.0;       // the noise standard deviation estimated from the data
};

// y: samples every dt seconds, at least 4, all finite. lambda > 0: that lambda; otherwise chosen
// automatically.
SmoothingSplineResult SmoothingSpline(const Eigen::VectorXd& y, double dt, double lambda = -1.0);

// The same with the derivative free to jump at `breaks` (sample indices, increasing): an
// independent natural spline on each stretch [break_k, break_k+1), all with one lambda, chosen
// automatically by C_L summed over the stretches. The derivative at a break is the right-hand
// one. Stretches of fewer than 4 samples are their least-squares line. For responses to
// piecewise-constant inputs, whose derivative jumps where an input steps (see StepBreaks in
// derivative.h), this removes the smoothing bias at the jumps.
SmoothingSplineResult PiecewiseSmoothingSpline(const Eigen::VectorXd& y, double dt,
                                               const std::vector<Eigen::Index>& breaks,
                                               double lambda = -1.0);

// The standard deviation of white noise on a smooth signal: the least over k = 4, 6, 8 of
// 1.4826 median|Delta^k y| / sqrt(C(2k, k)) (Delta^k of white noise has variance C(2k, k) sd^2;
// a smooth signal adds about dt^k y^(k), which falls with k, and each kink only k + 1
// outliers). Within a few % for n >= 1000 (1 % low on pure noise). O(n). Zero for noise-free
// polynomials of degree below 8, and for data quantised so coarsely that most differences are
// zero (pass lambda explicitly then).
double EstimateNoiseSd(const Eigen::VectorXd& y);

}  // namespace usvid
