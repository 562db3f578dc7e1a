#include "importers/column_map.h"

#include <set>

#include "core/error.h"
#include "core/units.h"

namespace usvid {

std::vector<ColumnMapping> ParseColumnMap(const std::vector<std::string>& items) {
  std::vector<ColumnMapping> map;
  std::set<std::string> targets;
  for (const std::string& item : items) {
    const std::string where = "--map '" + item + "': ";
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
      throw InputError(where + "expected NEW=OLD or NEW=OLD:unit");
    ColumnMapping m;
    m.target = item.substr(0, eq);
    std::string rest = item.substr(eq + 1);
    const auto colon = rest.rfind(':');
    if (colon != std::string::npos) {
      m.unit = rest.substr(colon + 1);
      rest = rest.substr(0, colon);
      try {
        m.factor = SiFactor(m.unit);
      } catch (const InputError& e) {
        throw InputError(where + e.what());
      }
    }
    if (rest.empty()) throw InputError(where + "no source column");
    m.source = rest;
    if (!targets.insert(m.target).second)
      throw InputError(where + "channel '" + m.target + "' is mapped twice");
    map.push_back(std::move(m));
  }
  return map;
}

}  // namespace usvid
