#include "metrics/maneuver_header.h"

#include <algorithm>
#include <cctype>
#include <regex>

#include "core/error.h"
#include "core/parse_number.h"
#include "maneuvers/maneuver_spec.h"

namespace usvid {
namespace {

// A degree mark after an angle: "°" (UTF-8), "deg", "degrees", or nothing.
constexpr const char* kDegreeMark = R"((?:\s*(?:°|º|deg(?:rees?)?))?)";
constexpr const char* kAngleText = R"((\d+(?:\.\d+)?))";

int SideOf(const std::string& lower) {
  const bool starboard = lower.find("starboard") != std::string::npos ||
                         std::regex_search(lower, std::regex(R"(\bstb\b|\(s\)|\bsb\b)"));
  const bool port = std::regex_search(lower, std::regex(R"(\bport\b|\(p\)|\bps\b)"));
  if (starboard == port) return 0;
  return starboard ? 1 : -1;
}

}  // namespace

NamedManeuver ParseManeuverHeader(const std::string& text, const std::string& where) {
  std::string lower = text;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const std::string trimmed = std::regex_replace(lower, std::regex(R"(^\s+|\s+$)"), "");
  auto fail = [&](const std::string& why) -> NamedManeuver {
    throw InputError(where + ": the maneuver '" + text + "' " + why +
                     " (known: Z20°/10° starting to starboard, zigzag:20/10, T35° to port, "
                     "turning:35; docs/data.md#the-records-maneuver-frecordjson)");
  };
  NamedManeuver m;
  std::smatch g;
  // usvid's own spec (maneuvers/maneuver_spec.h): the sign of A is the side (starboard positive).
  if (IsManeuverTest(trimmed) && trimmed.find(':') != std::string::npos) {
    ManeuverSpec spec;
    try {
      spec = ParseManeuverSpec(trimmed);
    } catch (const InputError&) {
      return fail("is none usvid knows");
    }
    const bool zigzag = spec.kind == ManeuverKind::kZigzag;
    if (spec.numbers.size() != (zigzag ? 2u : 1u)) return fail("is none usvid knows");
    m.kind = spec.name;
    m.rudder_deg = spec.RudderDeg();
    if (zigzag) m.check_deg = spec.numbers[1];
    m.side = spec.Side();
  } else if (std::regex_search(
                 trimmed, g,
                 std::regex(std::string(R"(^(?:z|zz|zig-?zag)\s*)") + kAngleText + kDegreeMark +
                            R"(\s*/\s*)" + kAngleText + kDegreeMark + R"((?:\s|$|,))"))) {
    m.kind = "zigzag";
    m.rudder_deg = ParseNumber(g[1].str()).value;
    m.check_deg = ParseNumber(g[2].str()).value;
    m.side = SideOf(trimmed);
  } else if (std::regex_search(
                 trimmed, g,
                 std::regex(std::string(R"(^(?:t|tc|turning(?:\s+circle)?|turn)\s*)") + kAngleText +
                            kDegreeMark + R"((?:\s|$|,))"))) {
    m.kind = "turning";
    m.rudder_deg = ParseNumber(g[1].str()).value;
    m.side = SideOf(trimmed);
  } else {
    return fail("is none usvid knows");
  }
  if (!(m.rudder_deg > 0 && m.rudder_deg <= 90))
    return fail("has a rudder angle outside (0, 90] deg");
  if (m.kind == "zigzag" && !(m.check_deg > 0 && m.check_deg <= 90))
    return fail("has a heading check outside (0, 90] deg");
  return m;
}

}  // namespace usvid
