// A maneuver spec (docs/data.md#maneuvers) parsed into its kind and its numbers:
// "zigzag:-20/20" -> a zig-zag, A -20 (to port first), B 20; "turning" -> a turning circle at the
// maneuver's default. Every reader of a spec goes through here: the factory builds maneuvers from
// it (maneuver_factory.h), the closed-loop replay reads a test's angles and side from it and
// mirrors it (metrics/closed_loop_replay.h), suites pick their jobs by kind, and the reading of
// a record writes one (metrics/maneuver_of_record.h). The defaults of a zig-zag (20/20) and of a
// turn (35) live here alone.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace usvid {

enum class ManeuverKind {
  kZigzag,
  kTurning,
  kStepGrid,
  kRandomSteps,
  kPrbs,
  kMultisine,
  kAutopilot,
  kUnknown,
};

inline constexpr double kDefaultZigzagDeg = 20.0;   // A and B of a bare "zigzag"
inline constexpr double kDefaultTurningDeg = 35.0;  // A of a bare "turning"

struct ManeuverSpec {
  ManeuverKind kind = ManeuverKind::kUnknown;
  std::string name;                // before ':'
  std::vector<double> numbers;     // after ':', separated by '/'; empty exactly without ':'
  std::vector<std::string> texts;  // the same numbers as written
  // A zig-zag replayed from a record reverses about a base course this far off the heading at
  // its execute (metrics/zigzag_response.h); not part of the text.
  double base_offset_rad = 0.0;

  // A test with ITTC criteria: a zig-zag or a turning circle.
  bool IsTest() const { return kind == ManeuverKind::kZigzag || kind == ManeuverKind::kTurning; }
  // A zig-zag's or a turn's rudder angle |A| [deg]; the kind's default without numbers.
  double RudderDeg() const;
  // A zig-zag's heading check |B| [deg]; 20 without it.
  double CheckDeg() const;
  // +1 when the first rudder order is to starboard (A >= 0, or no A), -1 to port.
  int Side() const { return numbers.empty() || numbers[0] >= 0 ? 1 : -1; }
  // The spec as written ("zigzag:-20/20"), base_offset_rad aside.
  std::string Text() const;
  // The same test to the other side, as written ("zigzag:-20/20" <-> "zigzag:20/20"); without
  // numbers, the kind's default to the other side ("turning" -> "turning:-35").
  std::string Mirrored() const;
};

// Throws InputError naming the spec for a number that does not parse.
ManeuverSpec ParseManeuverSpec(const std::string& spec);

// The kind a spec names, by its name before ':' (its numbers unread, so never throws); kUnknown
// for a name no maneuver has.
ManeuverKind KindOfManeuver(std::string_view spec);
// Whether the spec names a zig-zag or a turning circle.
bool IsManeuverTest(std::string_view spec);
// A zig-zag or turn named without its angles ("zigzag", "turning"): the record is to say them.
bool IsBareManeuverTest(std::string_view spec);

}  // namespace usvid
