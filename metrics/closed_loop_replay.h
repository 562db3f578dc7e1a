// Closed-loop replay of a test maneuver on an identified model, and the maneuver's criteria
// (ITTC 7.5-04-02-01, IMO MSC.137(76)) of the replay beside those of the held-out record.
//
// A zig-zag's rudder reverses when the heading crosses its threshold. Replaying the recorded
// rudder open-loop makes the model's reversals follow the true hull's heading, not its own, so
// the overshoots it shows are not the model's. Here the model runs the maneuver's own rule
// (maneuvers/: heading-triggered reversals, the vessel's yaw limits and rate), from the record's
// first state, with every other command (thrust, bucket) held at the record's first value (the
// record's approach: its speed and thrust). The criteria are read from the replay and from the
// record by the same analysis (metrics/zigzag_response.h, metrics/turning_response.h). A real
// log's approach (hand steering from rest) is cut off: both are read from the maneuvers'
// lead-in before the record's execute on (FromLeadIn), and a vessel model then starts from the
// recorded state there.
//
// Models: an equation model (metrics/equation_model.h) whose inputs are the vessel's commands,
// or the waterjet's actuator states or forces (preprocessing/waterjet_forces.h). Those follow the
// commands through actuator dynamics identified on the record itself
// (preprocessing/actuator_dynamics.h): the actuators are the test's hardware, the same for
// every model, not part of the hull model scored. An actuator whose command the record holds is
// held at its recorded median. A vessel model (nominal, refit, diagnose) runs the maneuver in
// its simulator, from steady state under the record's first commands.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/dataset.h"
#include "simulation/vessel_ref.h"

namespace usvid {

struct ClosedLoopReplay {
  Dataset run;  // t, the model's channels, the commands (the vessel's input names)
  bool diverged = false;
  double diverged_at_s = 0.0;
  std::string diverged_channel;
};

// Runs maneuver `spec` on `model` closed-loop, on `vessel`'s actuation, for as long as
// `recorded` lasts. Throws InputError saying why when the model cannot be replayed (an input
// that is neither a command nor derived from one, an actuator the record cannot identify).
// With `from_recorded_state`, a vessel model starts from the record's first row (its
// velocities) instead of its own steady state. A zig-zag reverses about a base course
// `base_course_offset_rad` off the model's heading at the execute: the record's, which
// ManeuverScorer reads once (metrics/zigzag_response.h).
ClosedLoopReplay ReplayManeuver(const nlohmann::json& model, const VesselRef& vessel,
                                const std::string& spec, const Dataset& recorded,
                                bool from_recorded_state = false,
                                double base_course_offset_rad = 0.0);

// The execute time of maneuver `spec` (zigzag or turning) in a record
// (metrics/maneuver_execute.h).
double ManeuverExecute(const std::string& spec, const Dataset& data, const std::string& heading,
                       const std::string& rudder);

// The record from maneuvers' lead-in (kLeadInS) before its execute on, its time from 0, when
// its approach is more than twice as long: a real log, whose hand steering while the ship
// gathers way is no part of the test. A record that starts at its lead-in (a simulated one), or
// a few seconds before (the MARIN tank tests: 7.4 s), is returned as it is.
Dataset FromLeadIn(const std::string& spec, const Dataset& recorded, const std::string& heading,
                   const std::string& rudder);

// The criteria of maneuver `spec` read from a record (null where the record cannot give one):
//   zigzag: first_overshoot_deg, second_overshoot_deg, second_execute_s (first execute to the
//           first reversal), period_s (first to third reversal);
//   turning: advance_m, transfer_m, tactical_diameter_m, steady_rate_deg_s.
// A record's execute is searched for (metrics/maneuver_execute.h); a `replay`'s is its first
// rudder movement, as the maneuver ran it.
nlohmann::json ManeuverCriteria(const std::string& spec, const Dataset& data,
                                const std::string& heading, const std::string& rudder,
                                bool replay = false);

// A record prepared for the closed-loop scores of many models (a calibration's scan,
// yaw_bias_calibration.h): cut from its lead-in once, its criteria read once. Score(model) is
// ClosedLoopScore's object for a replayable spec and a vessel. Not for concurrent use: the
// record's criteria are read on a model's first score.
class ManeuverScorer {
 public:
  // Throws InputError as ClosedLoopScore does for a record without the maneuver's channels, or
  // whose first turn goes the other way than `spec`'s.
  ManeuverScorer(const VesselRef& vessel, const std::string& spec, const Dataset& recorded);
  // `replay`: where the replay the criteria were read from is moved to, if given (left as it
  // was when the model cannot be replayed).
  nlohmann::json Score(const nlohmann::json& model, ClosedLoopReplay* replay = nullptr) const;
  // The replay Score reads its criteria from (the report's plan views, harness/plan_view.h);
  // throws InputError when the model cannot be replayed.
  ClosedLoopReplay Replay(const nlohmann::json& model) const;
  // The record as the replays start from it: cut from its lead-in, derived channels added.
  const Dataset& recorded() const { return recorded_; }
  const std::string& rudder() const { return rudder_; }
  double base_course_offset_rad() const { return base_course_offset_rad_; }

 private:
  VesselRef vessel_;
  std::string spec_, rudder_;
  Dataset recorded_;                                        // from the lead-in on
  std::optional<double> replayed_from_s_;                   // where it was cut, if it was
  double base_course_offset_rad_ = 0.0;                     // a zig-zag's, read from the record
  mutable std::map<std::string, nlohmann::json> measured_;  // by heading channel
};

// A row's "closed_loop" object: {"maneuver", "status", "measured": {criteria}, "model":
// {criteria}, and per criterion "<name>_error_<unit>" = model - measured (null when either is)}.
// status "ok"; "diverged at T s (channel)"; or "not replayable: why" (an open-loop maneuver, a
// record without a maneuver, a model that cannot run one): never a missing field, never throws
// for the model's sake (a record without the maneuver's channels still throws InputError).
// `replay`: as ManeuverScorer::Score's.
nlohmann::json ClosedLoopScore(const nlohmann::json& model, const VesselRef& vessel,
                               const std::string& spec, const Dataset& recorded,
                               ClosedLoopReplay* replay = nullptr);

// The spec that replays a measured record: "zigzag" or "turning" alone is the test the record
// holds, its angle and side read from it with `vessel`'s rudder (metrics/maneuver_of_record.h);
// any other spec, or one the record does not hold, is returned as it is. Measured records only:
// a simulated suite's "zigzag" is the maneuver it simulated (20/20).
std::string RecordedManeuverSpec(const std::string& spec, const VesselRef& vessel,
                                 const Dataset& recorded);

}  // namespace usvid
