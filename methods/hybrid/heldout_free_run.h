// The hybrid's check of a model by free run: the vessel with its parameters and terms simulated
// over each held-out record from the record's first row under its logged inputs, as scoring
// free-runs a model (metrics/free_run.h). The selection scores a term by multiple shooting, each
// segment's state re-estimated from the data, which does not see a term that makes the vessel
// unstable: on the Esso Osaka runs, at 3000 rows, r' += 10.5 |r| r (a yaw moment that grows
// with the rate, the wrong way) shortened the segments' error by a likelihood ratio of 1041, and
// its free runs left the bounds on 7 of 20 held-out runs. A term is chosen only when the free
// runs do not get worse with it (hybrid.h).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "effects/effect.h"
#include "simulation/vessel_ref.h"

namespace usvid::hybrid {

// The free runs' error of simulation/segment_error.h, each record of `heldout` (and each stretch
// between a log's own gaps) run whole from its first row: the squared errors of the `states`
// over each one's variance, averaged over the rows where it was sampled; +infinity when a run
// leaves the bounds of simulation/divergence_bounds.h. A caller that weighs a model only against
// a bound passes it as `stop_above`: once the error is sure to exceed it, the records left are
// not run and the error so far (a lower bound, above `stop_above`) is returned.
double HeldoutFreeRunError(const VesselRef& vessel, const Dataset& heldout,
                           const std::vector<double>& params, const std::vector<Effect>& terms,
                           const std::vector<std::string>& states,
                           double stop_above = std::numeric_limits<double>::infinity());

// The same, with each record's share of the error (NaN for a record left unrun). `likely`, a
// similar model's shares (or empty), runs the records it found worst first, so that a model
// worse than `stop_above` is stopped after fewer of them; a finished error does not depend on
// it (simulation/segment_error.h).
struct HeldoutFreeRun {
  double error = 0.0;
  std::vector<double> per_record;
};
HeldoutFreeRun HeldoutFreeRuns(const VesselRef& vessel, const Dataset& heldout,
                               const std::vector<double>& params, const std::vector<Effect>& terms,
                               const std::vector<std::string>& states,
                               double stop_above = std::numeric_limits<double>::infinity(),
                               const std::vector<double>& likely = {});

}  // namespace usvid::hybrid
