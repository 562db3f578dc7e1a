// The execute of a zig-zag or turning test in a record: where the test itself begins. A
// simulated record starts at its lead-in, so its first rudder movement is the execute. A real
// log often starts near rest, and the operator steers by hand while the ship gathers way; the
// test begins later, with the first full-angle order that is held until the heading has turned
// by the test's angle (the zig-zag's threshold, 90 deg for a turn). That order's movement starts
// at the execute (ITTC 7.5-04-02-01 counts from the first rudder movement of the order).
#pragma once

#include <span>

namespace usvid {

// `command`: the yaw command's samples; `heading` [rad] at the same samples. `full` is the
// test's rudder angle (the zig-zag's A), or 0 for the command's largest absolute value; an order
// is at full angle from full less max(moved, 10 % of full) up. It is held long enough when the
// heading has turned by 80 % of `turn` [rad] from the execute (the operator counts from the
// heading when the order is given; the hull has drifted a little while the rudder moved).
// Returns the execute's index: the first sample more than `moved` from the command's value
// before the order's movement began; -1 when no full-angle order is held that long (the caller
// then falls back to the first movement).
long FindExecute(std::span<const double> command, std::span<const double> heading, double moved,
                 double turn, double full = 0.0);

}  // namespace usvid
