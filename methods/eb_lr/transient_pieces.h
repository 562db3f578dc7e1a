// The transients of a step experiment, where eb-lr fits the masses (eb_lr.h, step 3): the runs
// of samples outside the steady windows, each reaching `margin` samples (at most half a window)
// into the windows around it, cut into pieces of `piece` samples (a last piece shorter than half
// of that joins the one before). Sample spans are inclusive.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "methods/eb_lr/steady_windows.h"

namespace usvid::eb_lr {

// n: the record's samples; windows in time order.
std::vector<SteadyWindow> TransientRuns(Eigen::Index n, const std::vector<SteadyWindow>& windows,
                                        Eigen::Index margin);

std::vector<SteadyWindow> TransientPieces(const std::vector<SteadyWindow>& runs, Eigen::Index piece);

// The integral rows' sum over a span: the trapezoid sum of f(k) (x_{k+1} - x_k), f evaluated at
// sample indices.
template <typename F>
double Stieltjes(const Eigen::VectorXd& x, const SteadyWindow& span, F f) {
  double sum = 0.0;
  for (Eigen::Index k = span.first; k < span.last; ++k)
    sum += 0.5 * (f(k) + f(k + 1)) * (x(k + 1) - x(k));
  return sum;
}

}  // namespace usvid::eb_lr
