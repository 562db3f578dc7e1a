// Term completion: each of GP's candidate equations offered once more with a small library of
// elementary terms added to its sum, the regime features and the products of two states, and
// the terms to keep chosen again by held-out error (term_selection.h).
//
// Why. The search ranks trees by the held-out r^2 of the derivative on the training record. A
// term that carries little of that variance there but sets a maneuver's outcome elsewhere is
// left out: trained on odin-hs's random steps, GP's surge equations lacked v*r, the speed lost to
// the sway-yaw coupling in a turn, which a zig-zag's surge is mostly made of (its u varies by
// 0.1 m/s). Such a term costs the search a subtree it must draw and keep against parsimony;
// offered as a column to the least-squares term selection, it is kept when the data support it,
// at one standard error, and the completed candidate then competes with the others in model
// selection by short-horizon simulation (model_selection.h), which keeps the smaller unless the
// completed one simulates better. The library holds no operator GP was not given.
// usvid identify turns it on where it was measured to help, on records with regime features,
// and adds to them the regime basis at eight knots, which the search is not given (four hinges
// there, regime_features.h): on odin-hs's zig-zag the finer basis and the products together
// lifted GP's surge, and neither alone did. On KVLCC2's single training zig-zag, with no regime
// features, the completed candidates fitted the training record's validation part and lost
// heading on the other zig-zag (docs/gp.md).
#pragma once

#include <vector>

#include "methods/gp/search.h"

namespace usvid::gp {

// Single-term trees: each of `features`' variables, then v_i*v_j for i <= j over `states`
// (variable indices into the problem's names), when the operator * is among `functions`.
std::vector<Tree> CompletionLibrary(const std::vector<int>& states,
                                    const std::vector<int>& features,
                                    const std::vector<Op>& functions);

// `model`'s terms and those of `library` it does not already have, refitted on `problem` with
// the terms chosen by `options` (term_selection.h unless a threshold is set).
Model CompleteTerms(const Model& model, const std::vector<Tree>& library, const GpProblem& problem,
                    const GpOptions& options);

}  // namespace usvid::gp
