// A maneuver spec (docs/data.md#maneuvers) split into its name and its numbers:
// "zigzag:-20/20" -> zigzag, {-20, 20}; "turning" -> turning, {} (the maneuver's defaults). The
// factory builds maneuvers from it (maneuver_factory.h), and the closed-loop replay reads a
// test's angles from it and mirrors its side (metrics/closed_loop_replay.h).
#pragma once

#include <string>
#include <vector>

namespace usvid {

struct ManeuverSpec {
  std::string name;
  std::vector<double> numbers;     // after ':', separated by '/'; empty exactly without ':'
  std::vector<std::string> texts;  // the same numbers as written

  // The spec with its first number's sign turned: the same test to the other side
  // ("zigzag:-20/20" <-> "zigzag:20/20"). Without numbers: `defaults` (e.g. "20/20") to the
  // other side.
  std::string Mirrored(const std::string& defaults) const;
};

// Throws InputError naming the spec for a number that does not parse.
ManeuverSpec ParseManeuverSpec(const std::string& spec);

}  // namespace usvid
