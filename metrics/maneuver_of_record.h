// Which zig-zag or turning test a record holds, read from the record itself: kind, rudder angle
// A, heading check B, side, execute and base course, and the spec that replays it closed-loop
// (metrics/closed_loop_replay.h). One reading serves `usvid info --zigzag`, `evaluate
// --maneuver zigzag`, the real suite's runs and a suite's own simulated records.
// - A is the angle the rudder is held at longest (to the degree, among angles of 5 deg or
//   more: an operator's rudder check at rest is short), to the nearest 5 deg when it lies within
//   1 deg of one (a logged angle reads a little off).
// - A zig-zag's B is read from its reversal orders (metrics/zigzag_response.h, ReadZigzagCheck),
//   not assumed equal to A: HSVA's KVLCC2 runs 20/10, 30/5, 10/1.
// - The side is the way the heading turns first after the execute (starboard positive), so
//   either rudder sign convention reads alike. A turn must turn by 90 deg.
// - A zig-zag's reversals are ordered at one heading off the base course: a record whose orders
//   scatter (ZigzagCheckReading::Consistent; a random run's rudder switched between +-35 deg)
//   holds no zig-zag.
// - A record of either kind (a folder that holds both, as MARIN's zz_ and tc_ files do) is told
//   apart by how it holds that angle: a test holds it in at least half of the rows steered past
//   5 deg (within 1.5 deg), a zig-zag to both sides (each side at least a fifth of those rows), a
//   turn to one.
// - A record whose log names its maneuver (metadata "maneuver", metrics/maneuver_header.h:
//   HSVA's "Z20°/10° starting to starboard") takes A and B from the name, and the side when the
//   name gives it, after checking them against the record: a name the record contradicts is
//   refused (InputError naming the file and what differs), never silently replayed.
#pragma once

#include <cmath>
#include <string>

#include "core/dataset.h"

namespace usvid {

struct TestOfRecord {
  std::string kind;              // "zigzag" or "turning"; "" when the record holds no such test
  double rudder_deg = 0.0;       // A (> 0)
  double check_deg = 0.0;        // a zig-zag's B (> 0)
  int first_turn = 0;            // +1 starboard, -1 port
  double execute_s = NAN;        // the test's execute
  double base_offset_deg = 0.0;  // a zig-zag's base course less the heading at the execute
  std::string named;             // the log's name of it, when it has one
  // "zigzag:-20/10" or "turning:35" (A signed by the first turn); "" without a test.
  std::string Spec() const;
};

// The test of `kind` "zigzag", "turning" or "any" (either) in `data`. Throws InputError naming
// the data's file when the heading or rudder channel is missing, or the log's name of its
// maneuver is unknown or contradicted by the record.
TestOfRecord ReadTestOfRecord(const Dataset& data, const std::string& kind,
                              const std::string& heading = "psi",
                              const std::string& rudder = "delta");

// ReadTestOfRecord(...).Spec().
std::string ManeuverOfRecord(const Dataset& data, const std::string& kind,
                             const std::string& heading = "psi",
                             const std::string& rudder = "delta");

}  // namespace usvid
