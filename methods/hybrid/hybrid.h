// `hybrid`: a registered vessel plus the discrepancy terms its physics lacks (Grey-box
// identification: the model a naval architect trusts, and what the data say it misses).
//  1. The training record is split: the first part fits, the last `heldout` part judges; joined
//     records one by one (core/records.h: SplitEachRecord), so that every record does both.
//  2. The vessel is refitted on the first part (methods/refit: its own coefficients, multiple
//     shooting, a prior around the published values).
//  3. Proposals: forward orthogonal least squares (term_proposals.h), per_state terms for each
//     dynamic state, on the derivative residual of the vessel as given and of the refitted one
//     (a refit that bends its coefficients towards a missing term can hide it).
//  4. Selection by simulation: each round, every remaining proposal is added to the terms
//     chosen so far, the vessel and all the terms fitted together on the first part by
//     multiple shooting, and the result scored on the held-out part (each segment's initial
//     state estimated, the model held). The best is kept when its likelihood ratio on the
//     held-out part passes a chi-square test (critical_ratio), and only if the held-out part's
//     free runs (heldout_free_run.h) are no worse with it; at most max_terms rounds. A
//     derivative residual proposes, the held-out simulation decides: on real data the proposals
//     with the largest ERR often chase noise in the differentiated states.
//  5. The vessel and the chosen terms are refitted together on the whole record.
// The model is a vessel model (like refit's) whose "effects" are the chosen missing terms, so
// `usvid evaluate`, `simulate --params` and `diagnose --params` run it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "methods/hybrid/free_coefficient_shape.h"
#include "methods/hybrid/term_proposals.h"
#include "methods/refit/refit.h"
#include "simulation/vessel_ref.h"

namespace usvid::hybrid {

// The name --method and suites give it (methods/method_list.h registers it).
inline constexpr std::string_view kMethodName = "hybrid";

struct HybridOptions {
  RefitOptions refit;  // free parameters, segment, prior; its terms are ignored
  // The most rows each proposal's fit and score use, spread over the first and the held-out
  // part (0: half of refit.max_rows, or all when that is 0). The search refits the vessel once
  // per proposal and round; the final fit (step 5) takes refit.max_rows.
  long search_rows = 0;
  double heldout = 1.0 / 3.0;  // fraction of the record (its end) that judges the terms
  int per_state = 3;           // proposals per dynamic state
  int max_terms = 3;           // rounds of selection (at most kMaxRefitTerms)
  // A term is kept when LR = N_eff ln(E_before / E_after) passes the chi-square test at 0.999
  // for one degree of freedom, N_eff the held-out residuals over their correlation time (of the
  // vessel alone): the diagnosis's rule (diagnosis/diagnose.h).
  double critical_ratio = 10.83;
  // A proposal whose term column is at least this close in shape (|cos|) to a freed
  // coefficient's derivative column is that coefficient, not a missing term, and is set aside
  // (free_coefficient_shape.h); 0: none is (every proposal still reports its closest).
  double set_aside_cosine = 0.0;
};

struct SelectionRound {
  std::vector<double> heldout_error;   // per proposal (infinity: already chosen or failed)
  std::vector<double> free_run_error;  // per proposal (heldout_free_run.h; infinity: diverged)
  double likelihood_ratio = 0.0;       // of the best
  int chosen = -1;                     // index into proposals; -1: none good enough, stop
};

struct HybridResult {
  RefitResult fit;  // the final fit: the vessel's parameters and the chosen terms
  std::vector<TermProposal> proposals;
  std::vector<CoefficientShape> proposal_shapes;  // per proposal: its closest freed coefficient
  // The proposals set aside as a freed coefficient's own shape (free_coefficient_shape.h), each
  // with that coefficient and the cosine.
  std::vector<std::pair<TermProposal, CoefficientShape>> set_aside;
  double vessel_heldout_error = 0.0;  // the refitted vessel alone, on the held-out part
  double effective_samples = 0.0;     // N_eff of the held-out part
  std::vector<SelectionRound> rounds;
  double heldout_error = 0.0;  // with the chosen terms (fitted on the first part)
  // The free runs of the held-out part (heldout_free_run.h): the vessel alone, and with the terms.
  double vessel_free_run_error = 0.0;
  double free_run_error = 0.0;
  double seconds = 0.0;
};

// Throws InputError as RefitVessel does, or for options out of range.
HybridResult IdentifyHybrid(const VesselRef& vessel, const Dataset& data,
                            const std::vector<double>& start, const HybridOptions& options);

}  // namespace usvid::hybrid
