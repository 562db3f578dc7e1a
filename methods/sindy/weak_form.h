// The weak (integral) form of x' = Theta(x, u) w (Messenger & Bortz 2021, "Weak SINDy"): each
// equation is multiplied by a smooth test function phi_k that vanishes at both ends of its
// window and integrated, and the derivative moves onto phi by parts,
//   - int phi_k'(t) x(t) dt = sum_j w_j int phi_k(t) theta_j(t) dt.
// The same coefficients w, in the same units, solve it; but no derivative of the data is taken:
// the measured x is only averaged (by phi_k'), so noise in x that a derivative amplifies (a GPS
// velocity that jumps after a dropout) is smoothed over the window instead. One row per window;
// windows overlap by half and never cross a gap (core/stretches.h), so records fitted jointly
// stay apart. docs/baselines.md#the-weak-form says when to use it and how the window is chosen.
//
// phi(s) = (1 - s^2)^4 on s in [-1, 1] (s = the window's time scaled to [-1, 1]): zero with its
// first three derivatives at both ends, so the integration by parts has no boundary terms and
// the rows weight the window's middle most. phi is scaled to integrate to 1, so a row is a
// weighted mean: the weak target is in the derivative's units, and so are held-out errors.
// Integrals by the trapezoid rule on the grid (uniform after preprocessing).
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace usvid::sindy {

// The windows of `window_rows` rows (odd, at least 5) at a half-window stride inside each
// stretch of the grid `t`; a stretch shorter than one window gives none. Rows [first, end).
struct WeakWindows {
  std::vector<std::pair<Eigen::Index, Eigen::Index>> windows;
  // The windows of each stretch, as ranges [first, end) of window indices (cross-validation
  // folds cut each of them: preprocessing/splits.h).
  std::vector<std::pair<Eigen::Index, Eigen::Index>> stretches;
  // The quadrature weights of phi and of phi' at the rows of a window (dt included): the same
  // for every window on a uniform grid.
  Eigen::VectorXd phi, dphi;
};

// Throws InputError for window_rows below 5.
WeakWindows MakeWeakWindows(const Eigen::VectorXd& t, Eigen::Index window_rows);

// The rows of a window of `seconds` on the grid `t`: seconds / dt + 1, odd, at least 5.
Eigen::Index WeakWindowRows(const Eigen::VectorXd& t, double seconds);

// The longest window of at most `seconds` (a whole number of grid steps) that still gives
// `min_windows` windows on the grid `t`; 0 when not even a 5-row window does.
double LongestWeakWindow(const Eigen::VectorXd& t, double seconds, Eigen::Index min_windows);

// int phi_k theta_j dt for each window k (rows) and column j.
Eigen::MatrixXd WeakColumns(const WeakWindows& w, const Eigen::MatrixXd& columns);

// - int phi_k' x dt for each window k: the weak counterpart of x'.
Eigen::VectorXd WeakTarget(const WeakWindows& w, const Eigen::VectorXd& x);

}  // namespace usvid::sindy
