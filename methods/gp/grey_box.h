// Grey-box GP-SR (`usvid identify --method gp --base VESSEL`; docs/gp.md#grey-box): GP searches
// additive corrections to a known vessel model instead of whole equations, so that the model a
// naval architect builds from the main particulars stays, and the data add what it lacks.
//  1. Each training record is split (core/records.h: SplitEachRecord): the first part fits, the
//     last part judges.
//  2. On the first part, the vessel's derivative residual d_s = s_dot - f_s(x, u; vessel) of each
//     dynamic state s (methods/refit/refit.h: DerivativeResidual) is the GP's target, over the
//     vessel's states and inputs (and the rudder's inflow terms on request). Each state's search
//     gives a front of corrections, from one term to many.
//  3. Selection on what is scored: the vessel with a candidate correction is free-run over the
//     held-out part of every record (methods/hybrid/heldout_free_run.h); each round keeps, of
//     the corrections within `parsimony` of the round's lowest error, the smallest, when it
//     lowers the error by `min_gain` at least; one state at a time, until none does. A
//     derivative residual proposes; the free run decides, so the vessel as given is always a
//     candidate.
//  4. The kept corrections' weights are refitted by least squares on the whole record.
// The model is a vessel model whose effects are the kept terms (missing_term: d(state)/dt +=
// coefficient * term), so `usvid evaluate`, `simulate --params` and suites run it.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "effects/effect.h"
#include "methods/gp/search.h"
#include "methods/regime_features.h"
#include "simulation/vessel_ref.h"

namespace usvid::gp {

struct GreyBoxOptions {
  GpOptions search;
  std::vector<DerivedVariable> features;  // besides the vessel's states and inputs
  double heldout = 1.0 / 3.0;             // the share of each record (its end) that judges
  int candidates_per_state = 6;           // points of each state's front tried, spread by size
  // A correction is kept when it lowers the held-out free runs' error by at least this share:
  // below it, on a simulated record whose vessel lacked only r' += 0.05 |v| v, the corrections
  // that followed the one to r were the noise's (u' and v' at 10 % of an error 0.1 % of the
  // vessel's own).
  double min_gain = 0.2;
  // Among the corrections whose error is within this share of the round's best, the smallest.
  double parsimony = 0.02;
};

struct GreyBoxCandidate {
  std::string state;
  std::string equation;       // the correction, as fitted on the first part
  double free_run_error = 0;  // the held-out free runs with it added (infinity: diverged)
  int round = -1;             // the round it was tried in
  // Its free runs were stopped once the error was sure to exceed what could be kept (or, in the
  // first round, the vessel's own): free_run_error is a lower bound.
  bool free_run_error_at_least = false;
};

// A model the selection weighed: the vessel with some corrections, their weights on every row.
struct GreyBoxAlternative {
  std::string label;  // "vessel", or the corrections: "r (size 9) + u (size 5)"
  std::vector<Effect> terms;
  std::map<std::string, std::string> corrections;  // state -> the correction
  double free_run_error = 0.0;           // on the held-out parts, weights of the first parts
  bool free_run_error_at_least = false;  // a lower bound, above the vessel's own
};

struct GreyBoxResult {
  std::vector<Effect> terms;                       // the kept corrections, weights on every row
  std::map<std::string, std::string> corrections;  // state -> the kept correction
  // What a choice by other criteria (the closed-loop tests of the training records,
  // metrics/closed_loop_choice.h) weighs: the vessel as given, each state's candidate
  // corrections alone, and each step of the forward selection; the kept model among them.
  std::vector<GreyBoxAlternative> alternatives;
  std::vector<GreyBoxCandidate> tried;
  double vessel_free_run_error = 0.0;  // the vessel as given, on the held-out parts
  double free_run_error = 0.0;         // with the kept corrections (fitted on the first parts)
  double node_evaluations = 0.0;
};

// The corrections to `vessel` with parameters `params` that `data` (raw records: states and the
// vessel's inputs) supports. Throws InputError naming what is missing (a state column, rows).
GreyBoxResult IdentifyGreyBox(const VesselRef& vessel, const std::vector<double>& params,
                              const Dataset& data, const GreyBoxOptions& options);

}  // namespace usvid::gp
