#include "maneuvers/maneuver_spec.h"

#include "core/error.h"
#include "core/parse_number.h"

namespace usvid {

ManeuverSpec ParseManeuverSpec(const std::string& spec) {
  ManeuverSpec out;
  const auto colon = spec.find(':');
  out.name = spec.substr(0, colon);
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

std::string ManeuverSpec::Mirrored(const std::string& defaults) const {
  if (texts.empty()) return name + ":-" + defaults;
  const std::string& first = texts.front();
  std::string out = name + ":" + (first.starts_with('-') ? first.substr(1) : "-" + first);
  for (size_t i = 1; i < texts.size(); ++i) out += "/" + texts[i];
  return out;
}

}  // namespace usvid
