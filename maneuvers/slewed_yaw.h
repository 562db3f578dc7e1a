// The yaw command of a classic maneuver (zig-zag, turning), moved no faster than the vessel's
// Actuation::yaw_rate_limit: it rests at neutral until the maneuver executes, then slews
// towards each target it is given. The time it rested counts for nothing.
#pragma once

#include "maneuvers/maneuver.h"

namespace usvid {

class SlewedYaw {
 public:
  // The command at time t while the rudder rests (neutral).
  double Rest(const Actuation& act, double t) {
    Start(act, t);
    last_t_ = t;
    return yaw_;
  }
  // The command at time t on its way to `target`.
  double Toward(const Actuation& act, double t, double target) {
    Start(act, t);
    yaw_ = act.SlewYaw(yaw_, target, t - last_t_);
    last_t_ = t;
    return yaw_;
  }

 private:
  void Start(const Actuation& act, double t) {
    if (started_) return;
    yaw_ = act.neutral[act.yaw_input];
    last_t_ = t;
    started_ = true;
  }
  double yaw_ = 0.0, last_t_ = 0.0;
  bool started_ = false;
};

}  // namespace usvid
