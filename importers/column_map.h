// A column map for `usvid import --format csv --map NEW=OLD[:unit],...`: the data channel
// NEW is taken from the log's column OLD, times the unit's factor to SI (core/units.h).
// Two targets are special: vn and ve (earth-fixed north and east velocity) are rotated into
// body-fixed u and v with psi.
#pragma once

#include <string>
#include <vector>

namespace usvid {

struct ColumnMapping {
  std::string target;
  std::string source;
  std::string unit;  // empty: taken as it is
  double factor = 1.0;
};

// Throws InputError naming the offending item (e.g. "--map 'u=speed:furlongs': unknown unit").
std::vector<ColumnMapping> ParseColumnMap(const std::vector<std::string>& items);

}  // namespace usvid
