#include <algorithm>
#include <cmath>
#include <numbers>

#include "maneuvers/maneuver.h"

namespace usvid {

double Actuation::YawCommand(double deg) const {
  const double command =
      yaw_sign * (yaw_is_angle ? deg * std::numbers::pi / 180.0 : deg / yaw_full_deg * yaw_full);
  return std::clamp(command, input_min[yaw_input], input_max[yaw_input]);
}

double Actuation::SlewYaw(double from, double to, double dt) const {
  if (!(yaw_rate_limit > 0)) return to;
  const double step = yaw_rate_limit * std::max(0.0, dt);
  return from + std::clamp(to - from, -step, step);
}

double Actuation::Speed(std::span<const double> state) const {
  if (speed_state < 0) return 0.0;
  return speed_is_surge ? std::hypot(state[speed_state], state[speed_state + 1])
                        : state[speed_state];
}

}  // namespace usvid
