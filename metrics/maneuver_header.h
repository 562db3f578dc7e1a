// The maneuver a log's header names, as a tank writes it: HSVA's "Z20°/10° starting to
// starboard" or "Z10°/1°", "zig-zag 20/10 to port", "T35° to port", "turning circle 35 deg", or
// usvid's own spec ("zigzag:20/10", "turning:-35"; docs/data.md#maneuvers). An importer keeps the
// header's text in the record (metadata "maneuver", docs/data.md#the-records-maneuver-frecordjson);
// the reading of a test (metrics/maneuver_of_record.h) uses the header's angles and checks them,
// and its side when it names one, against what the record shows.
#pragma once

#include <string>

namespace usvid {

struct NamedManeuver {
  std::string kind;        // "zigzag" or "turning"
  double rudder_deg = 0;   // A, > 0
  double check_deg = 0;    // a zig-zag's B (the heading change at which it reverses), > 0
  int side = 0;            // the first turn: +1 starboard, -1 port, 0 not named
};

// Throws InputError, naming `where` (the file) and the text, for a header that names no maneuver
// usvid knows (or an angle out of range: A in (0, 90], B in (0, 90]).
NamedManeuver ParseManeuverHeader(const std::string& text, const std::string& where);

}  // namespace usvid
