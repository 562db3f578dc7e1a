#include "core/units.h"

#include <numbers>
#include <utility>

#include "core/error.h"

namespace usvid {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr std::pair<const char*, double> kUnits[] = {
    {"deg", kDeg},
    {"deg/s", kDeg},
    {"knots", 1852.0 / 3600.0},
    {"kn", 1852.0 / 3600.0},
    {"km/h", 1.0 / 3.6},
    {"rpm", 2.0 * std::numbers::pi / 60.0},
    {"ms", 1e-3},
    {"rad", 1.0},
    {"rad/s", 1.0},
    {"m", 1.0},
    {"m/s", 1.0},
    {"s", 1.0},
    {"N", 1.0},
    {"Nm", 1.0},
    {"1", 1.0},
};

}  // namespace

double SiFactor(const std::string& unit) {
  std::string known;
  for (const auto& [name, factor] : kUnits) {
    if (unit == name) return factor;
    known += known.empty() ? name : std::string(", ") + name;
  }
  throw InputError("unknown unit '" + unit + "' (known: " + known + ")");
}

}  // namespace usvid
