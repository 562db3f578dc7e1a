// How many of a tree's terms to keep, chosen by the data instead of a hand-set ERR threshold:
// held-out error over contiguous blocks (blocked K-fold cross-validation).
//
// The rows are cut into K contiguous blocks and the normal equations of [1, t_1 .. t_k]
// against y are accumulated per block (ols.h). Terms enter in forward orthogonal order (OLS-FR,
// Chen, Billings & Luo 1989): at each step the term with the largest error reduction ratio given
// those already in. For each prefix of that order, the weights fitted on all blocks but b
// predict block b; from the Gram matrices alone, without touching rows again,
//   SSE_b = y_b'y_b - 2 w' X_b'y_b + w' X_b'X_b w,   w = (G - G_b)^-1 (X'y - X_b'y_b).
// Of the prefixes, the shortest whose held-out SSE exceeds the smallest by no more than one
// standard error of the excess (over blocks, paired) is kept, at least one term, refitted on
// all rows: the one-standard-error rule, so that a term which only fits noise, and helps
// held-out error by chance, is not kept.
// Contiguous blocks, not scattered rows: neighbouring samples share the derivative estimate's
// smoothing error, so scattered held-out rows would reward terms that fit that error.
// The held-out r^2 = 1 - sum SSE_b / SST is what the search ranks trees by.
#pragma once

#include <vector>

#include "methods/gp/ols.h"

namespace usvid::gp {

inline constexpr int kHeldOutBlocks = 5;

// `blocks`: the normal equations of each block (all with the same terms). An invalid fit for
// degenerate data, as FitOls.
OlsFit FitOlsHeldOut(const std::vector<NormalEquations>& blocks);

}  // namespace usvid::gp
