// How fast a record's yaw command (a rudder, a nozzle) moves, and so how the closed-loop replay of
// a model identified from such records moves it (metrics/closed_loop_replay.h).
//
// A data-driven model maps the logged yaw channel to the motion. Where the log holds the rudder's
// angle, the channel moves at the steering gear's rate (MARIN's KVLCC2 at 2.3 deg/s full scale,
// HSVA's at 13 deg/s model scale), and the replay slews the command at the vessel's rate, as the
// test did. Where the log holds the order, the channel jumps: Esso Osaka's pond tests put the
// rudder over by 40 deg between two samples at 10 Hz. A model fitted to them learned the hull's
// response to the order, with the steering gear's lag inside it; slewed again at the vessel's
// rate in the replay, that lag counted twice, and every replayed zig-zag checked its swing late
// (docs/compare.md#the-rudder-as-the-record-moves-it). So an equation model's replay steps its
// command where the record's channel steps. A vessel model (nominal, refit, grey-box GP)
// simulates its steering gear itself and keeps the vessel's rate.
#pragma once

#include <string>

#include "core/dataset.h"
#include "maneuvers/maneuver.h"

namespace usvid {

// The median rate [channel units/s] of the record's large moves of `channel`. A move is a run of
// samples that change the same way, held values inside it included, ended by a change the other
// way or by a hold longer than 1 s; its rate is its change over the time from its first change
// to its last. The large moves change by at least half the largest move and by at least
// `min_move`. 0 when the channel has no such move (or the record has no such channel).
double LargeMoveRate(const Dataset& recorded, const std::string& channel, double min_move);

// The yaw rate limit the replay of an equation model on `recorded` uses: 0 (the command steps, as
// the record's did) where the record's yaw channel moves by 2 deg or more at over twice the
// vessel's limit in its large moves; otherwise act.yaw_rate_limit.
double ReplayYawRateLimit(const Actuation& act, const Dataset& recorded);

}  // namespace usvid
