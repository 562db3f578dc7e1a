// Unit names accepted in column maps (usvid import --map NEW=OLD:unit) and their factor to SI:
// deg -> rad, deg/s -> rad/s, knots (kn) -> m/s, km/h -> m/s, rpm -> rad/s, ms -> s; the SI
// names (rad, rad/s, m, m/s, s, N, Nm, 1) have factor 1.
#pragma once

#include <string>

namespace usvid {

// Throws InputError listing the known units when `unit` is not one of them.
double SiFactor(const std::string& unit);

}  // namespace usvid
