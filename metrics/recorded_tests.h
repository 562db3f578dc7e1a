// The closed-loop tests among a fit's training records: each record of a joined record (core/
// records.h) that holds a zig-zag or a turning circle, read from the record
// (closed_loop_replay.h: RecordedManeuverSpec) and ready to replay a model on. What a model is
// calibrated or chosen by after its fit (yaw_bias_calibration.h, closed_loop_choice.h).
#pragma once

#include <string>
#include <vector>

#include "core/dataset.h"
#include "metrics/closed_loop_replay.h"
#include "simulation/vessel_ref.h"

namespace usvid {

struct RecordedTest {
  std::string spec;  // zigzag:A/B or turning:A, read from the record
  ManeuverScorer scorer;
};

// The records of `train` that hold a test of one of `kinds` ("zigzag", "turning"; the first
// that a record holds), each with its time from 0, replayed on `vessel`'s rudder. A record
// without a heading or rudder, or that holds none of them, is left out.
std::vector<RecordedTest> RecordedTests(const Dataset& train, const VesselRef& vessel,
                                        const std::vector<std::string>& kinds);

}  // namespace usvid
