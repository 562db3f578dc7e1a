#include "maneuvers/maneuver_spec.h"

#include <cmath>

#include "core/error.h"
#include "core/parse_number.h"

namespace usvid {

namespace {

struct KindName {
  std::string_view name;
  ManeuverKind kind;
};
constexpr KindName kKinds[] = {
    {"zigzag", ManeuverKind::kZigzag},       {"turning", ManeuverKind::kTurning},
    {"stepgrid", ManeuverKind::kStepGrid},   {"random-steps", ManeuverKind::kRandomSteps},
    {"prbs", ManeuverKind::kPrbs},           {"multisine", ManeuverKind::kMultisine},
    {"autopilot", ManeuverKind::kAutopilot},
};

}  // namespace

ManeuverKind KindOfManeuver(std::string_view spec) {
  const std::string_view name = spec.substr(0, spec.find(':'));
  for (const KindName& k : kKinds)
    if (k.name == name) return k.kind;
  return ManeuverKind::kUnknown;
}

bool IsManeuverTest(std::string_view spec) {
  const ManeuverKind kind = KindOfManeuver(spec);
  return kind == ManeuverKind::kZigzag || kind == ManeuverKind::kTurning;
}

bool IsBareManeuverTest(std::string_view spec) {
  return IsManeuverTest(spec) && spec.find(':') == std::string_view::npos;
}

ManeuverSpec ParseManeuverSpec(const std::string& spec) {
  ManeuverSpec out;
  const auto colon = spec.find(':');
  out.name = spec.substr(0, colon);
  out.kind = KindOfManeuver(out.name);
  if (colon == std::string::npos) return out;
  const std::string args = spec.substr(colon + 1);
  size_t start = 0;
  while (true) {
    const auto slash = args.find('/', start);
    const std::string item = args.substr(start, slash == std::string::npos ? slash : slash - start);
    const ParsedNumber p = ParseNumber(item);
    if (p.status != NumberStatus::kOk)
      throw InputError("--maneuver '" + spec + "': " + DescribeNumberStatus(p.status, item));
    out.numbers.push_back(p.value);
    out.texts.push_back(item);
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  return out;
}

double ManeuverSpec::RudderDeg() const {
  if (!numbers.empty()) return std::abs(numbers[0]);
  return kind == ManeuverKind::kTurning ? kDefaultTurningDeg : kDefaultZigzagDeg;
}

double ManeuverSpec::CheckDeg() const {
  return numbers.size() < 2 ? kDefaultZigzagDeg : std::abs(numbers[1]);
}

std::string ManeuverSpec::Text() const {
  std::string out = name;
  for (size_t i = 0; i < texts.size(); ++i) out += (i == 0 ? ":" : "/") + texts[i];
  return out;
}

std::string ManeuverSpec::Mirrored() const {
  if (texts.empty()) {
    const double a = RudderDeg();
    std::string out = name + ":-" + std::to_string(static_cast<int>(a));
    if (kind == ManeuverKind::kZigzag) out += "/" + std::to_string(static_cast<int>(CheckDeg()));
    return out;
  }
  const std::string& first = texts.front();
  std::string out = name + ":" + (first.starts_with('-') ? first.substr(1) : "-" + first);
  for (size_t i = 1; i < texts.size(); ++i) out += "/" + texts[i];
  return out;
}

}  // namespace usvid
