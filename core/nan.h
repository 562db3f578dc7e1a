// A quiet NaN: the value of a number not known (an unsampled row, a score that cannot be formed).
#pragma once

#include <limits>

namespace usvid {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace usvid
