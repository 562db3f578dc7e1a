// A grey-box model chosen by the tests a naval architect reads: among the alternatives a fit
// weighed (methods/gp/grey_box.h: the vessel as given, each candidate correction alone, each step
// of the forward selection), the one with the lowest held-out free-run error among those that do
// the training records' own zig-zags and turning circles, replayed closed-loop by their own rule
// (closed_loop_replay.h), no worse than the vessel as given: a mean first-overshoot error and a
// mean tactical-diameter error each at most the vessel's. The vessel as given is always among
// them, so a correction that bends the closed-loop tests is never kept for its free run.
//
// Why: on the Esso Osaka runs the free runs chose u' += 1.25 r^2 (the particulars' hull loses too
// much speed in a turn); its turning circles came out twice as far off in diameter as the
// vessel's (docs/gp.md#grey-box). A free run weighs every row of u, v and r alike; a circle's
// diameter is the speed over the rate of turn in the steady turn, a few rows of the record.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/dataset.h"
#include "simulation/vessel_ref.h"

namespace usvid {

// When `model` asks for it (model["calibration"]["choose"] == "closed-loop", as GP writes with
// `--base`), sets its "effects" and "corrections" to those of the alternative chosen as above
// among model["alternatives"] (each: label, corrections, effects, free_run_error, the first the
// vessel as given), from the zig-zags and turning circles among the
// records of `train` (one record or several joined: core/records.h), replayed on `vessel`'s
// rudder (empty: the model's vessel). The alternatives are replayed in the order of their
// free-run errors, below the vessel's, until one is admissible. Returns the report that replaces
// the request: applied, chosen, reason, maneuvers, and per alternative its label and free-run
// error, and where it was replayed its mean errors and whether it was admissible ("replayed":
// false otherwise). With no such test among the records the model is left as fitted.
nlohmann::json ChooseByClosedLoop(nlohmann::json& model, const Dataset& train,
                                  const VesselRef& vessel);

}  // namespace usvid
