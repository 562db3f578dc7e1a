// The value part of a scalar: itself for double, the real part for ceres::Jet. Step-size
// control and switching logic decide on values, never on derivative parts.
#pragma once

#include <ceres/jet.h>

namespace usvid {

inline double ValueOf(double x) { return x; }

template <typename T, int N>
double ValueOf(const ceres::Jet<T, N>& x) {
  return ValueOf(x.a);
}

}  // namespace usvid
