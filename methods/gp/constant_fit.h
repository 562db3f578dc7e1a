// Constant optimisation (Operon's local search): the numbers inside a model's terms, such as c
// in abs(u - c) or tanh(c v), tuned together with the term weights and the bias by
// Levenberg-Marquardt (Ceres), minimising
//   sum_i (y_i - b - sum_t w_t term_t(x_i; c))^2
// with automatic derivatives through the tree (every node evaluated on ceres::Jet). OLS fits the
// weights but cannot move a constant inside a nonlinear function; this can. Constants that only
// scale a term (a product of constants and variables) are left alone: the weight already does
// that, and they would make the problem rank-deficient.
#pragma once

#include <vector>

#include "methods/gp/search.h"

namespace usvid::gp {

struct ConstantFitResult {
  Tree tree;                                    // with the tuned constants
  double initial_cost = 0.0, final_cost = 0.0;  // half the sum of squared residuals
  int iterations = 0;
  bool improved = false;  // final < initial, and every value finite
};

// True when `model` has a constant that is more than a scale factor of its term.
bool HasTunableConstants(const Model& model);

// At most `iterations` LM iterations on the rows of `columns` (one pointer per variable, `rows`
// values each) against `target`. Single-threaded and deterministic.
ConstantFitResult FitConstants(const Model& model, const std::vector<const double*>& columns,
                               const double* target, long rows, int iterations);

}  // namespace usvid::gp
