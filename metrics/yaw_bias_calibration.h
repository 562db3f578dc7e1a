// A model's yaw constant set by the zig-zags it was trained on, replayed closed-loop
// (closed_loop_replay.h): the constant of the r equation that gives the model each training
// zig-zag's first and second overshoots, which fall to either side.
//
// Why: a hull's yaw is not quite symmetric (a single propeller's side force, a rudder's neutral
// angle, a gyro's offset), and a zig-zag overshoots further to one side than to the other
// (MARIN's KVLCC2: 15.7 deg to port first, 12.6 deg to starboard first). In an equation model
// that asymmetry rides on the yaw equation's constant. Fitted by equation error, that constant is
// a small number among the derivative's noise and the gyro's offset, and the model carries the
// trained side's overshoot to the other side (docs/real-data.md#kvlcc2-yaw-bias). The training
// zig-zag itself holds both sides: its first overshoot falls to one, its second to the other. The
// constant that gives the model both, replayed by the maneuver's own rule from the record's
// approach, is the one the record measures. One number is fitted to two criteria or more, so it
// cannot follow the noise of one.
//
// How: the squared errors of every training zig-zag's first and second overshoots, summed, are
// scanned over constants added to the equation's own, within half the spread of the r equation
// over the training rows (21 points), and the best is refined by golden-section search. The new
// constant is kept when it lowers that sum; the report says so either way.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/dataset.h"
#include "simulation/vessel_ref.h"

namespace usvid {

// When `model` asks for it (model["calibration"]["yaw_bias"] == "zigzag", as GP writes with
// `--yaw-bias zigzag`), sets its r equation's constant as above, from the zig-zags among the
// records of `train` (one record, or several joined: core/records.h), replayed on `vessel`'s rudder
// (`vessel` empty: the model's). model["calibration"]["yaw_bias"] becomes the report:
//   applied (bool), reason, maneuvers (each zig-zag's spec), shift (added to the constant),
//   constant_before, constant_after, overshoot_errors_before / _after (deg, each zig-zag's
//   first and second), and the replay's status where a zig-zag could not be replayed.
// A model that does not ask is left as it is. Before it, a grey-box model that asks for it
// (model["calibration"]["choose"] == "closed-loop") is chosen among its alternatives by the
// training records' closed-loop tests (closed_loop_choice.h).
void CalibrateRequested(nlohmann::json& model, const Dataset& train, const VesselRef& vessel);

// The calibration itself, for a model with an r equation; returns the report above.
nlohmann::json CalibrateYawBias(nlohmann::json& model, const Dataset& train,
                                const VesselRef& vessel);

}  // namespace usvid
