// What a naval architect looks at first in a measured test: the track in plan. For a held-out
// record that holds a zig-zag or a turning circle, the record and each model's closed-loop replay
// of it (metrics/closed_loop_replay.h) drawn north against east from the execute's lead-in, on
// one scale; on a turning circle each track marked where it has turned 90 deg (the advance) and
// 180 deg (the tactical diameter); on a zig-zag, beside it, the heading and the rudder against
// time, with the band of +-B about the base course outside which the overshoots lie.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "metrics/closed_loop_replay.h"

namespace usvid {

// A model a plan view draws: its label, its model.json, and the replay of this record its row
// was scored on (null: the plan view replays the model itself).
struct PlannedModel {
  std::string label;
  nlohmann::json model;
  std::shared_ptr<const ClosedLoopReplay> replay;
};

// `models`: in the order drawn; models that cannot be replayed are left out. `spec`: the
// maneuver the record holds (RecordedManeuverSpec). The SVG figures: the plan, then on a zig-zag
// the heading and rudder; none when the spec has no criteria, the record lacks north and east,
// or the maneuver cannot be read from it.
std::vector<std::string> PlanView(const std::string& title, const std::string& vessel,
                                  const std::string& spec, const Dataset& held,
                                  const std::vector<PlannedModel>& models);

}  // namespace usvid
