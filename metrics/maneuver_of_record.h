// Which zig-zag or turning test a record holds, read from the record itself: the spec that
// replays it closed-loop (metrics/closed_loop_replay.h), for a record whose file names no angle.
// The rudder angle A is the angle the rudder is held at longest (to the degree, among angles of
// 5 deg or more: an operator's rudder check at rest is short), to the nearest 5 deg when it lies
// within 1 deg of one (tests are run at 10, 15, 20, 35 deg; a logged angle reads a little off).
// A zig-zag is taken as A/A, the usual form; its sign, and a turn's, is the way the heading
// turns first after the execute (starboard positive). A turn must turn by 90 deg. A record of
// either kind (a folder that holds both, as MARIN's zz_ and tc_ files do) is told apart by how
// it holds that angle: a test holds it in at least half of the rows steered past 5 deg (within
// 1.5 deg), a zig-zag to both sides (each side at least a fifth of those rows), a turn to one. The
// real suite gives the further runs of its zig-zag, turning and mixed folders these specs
// (docs/compare.md#the-real-suite), so that the papers' own test runs, dropped into the folder,
// are replayed as the listed ones are.
#pragma once

#include <string>

#include "core/dataset.h"

namespace usvid {

// "zigzag:-20/20" or "turning:35" for `kind` "zigzag" or "turning", either for "any"; "" when
// the record holds no such test (no rudder order, no angle held, or no heading turned by the
// threshold after one). Throws InputError naming the data's file when the heading or rudder
// channel is missing.
std::string ManeuverOfRecord(const Dataset& data, const std::string& kind,
                             const std::string& heading = "psi",
                             const std::string& rudder = "delta");

}  // namespace usvid
