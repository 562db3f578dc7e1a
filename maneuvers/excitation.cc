#include "maneuvers/excitation.h"

#include <algorithm>

namespace usvid {

std::pair<double, double> ExcitationRange(const Actuation& act, int i) {
  const double lo = act.input_min[i], hi = act.input_max[i];
  switch (act.roles[i]) {
    case InputRole::kThrust:
      return {std::max(lo, 0.0) + 0.1 * (hi - std::max(lo, 0.0)), hi};
    case InputRole::kYaw:
      return {std::max(lo, -act.yaw_full), std::min(hi, act.yaw_full)};
    case InputRole::kSide:
      return {lo, hi};
    case InputRole::kFixed:
    case InputRole::kMeasured:
      break;
  }
  return {act.neutral[i], act.neutral[i]};
}

std::vector<double> CruiseCommand(const Actuation& act) {
  std::vector<double> u = act.neutral;
  if (act.thrust_input >= 0) u[act.thrust_input] = act.thrust_cruise;
  return u;
}

}  // namespace usvid
