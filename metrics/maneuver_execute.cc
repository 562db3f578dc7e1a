#include "metrics/maneuver_execute.h"

#include <algorithm>
#include <cmath>

namespace usvid {

long FindExecute(std::span<const double> command, std::span<const double> heading, double moved,
                 double turn, double full) {
  const long n = static_cast<long>(std::min(command.size(), heading.size()));
  if (full <= 0)
    for (long k = 0; k < n; ++k) full = std::max(full, std::abs(command[k]));
  const double at_full = full - std::max(moved, 0.1 * full);
  turn *= 0.8;
  for (long k = 0; k < n; ++k) {
    if (std::abs(command[k]) < at_full || full <= moved) continue;
    const double side = command[k] > 0 ? 1.0 : -1.0;
    // Back to the command's value before this order's movement began.
    long rest = k;
    while (rest > 0 && side * (command[rest] - command[rest - 1]) > 0) --rest;
    long execute = rest;
    while (execute < k && std::abs(command[execute] - command[rest]) <= moved) ++execute;
    const bool moves = std::abs(command[execute] - command[rest]) > moved;
    // Held at full angle until the heading has turned by `turn`? A zig-zag reverses at the
    // sample where the heading reaches its threshold, so that sample counts too.
    long held = k;
    for (; held < n && side * command[held] >= at_full; ++held)
      if (moves && std::abs(heading[held] - heading[execute]) >= turn) return execute;
    if (moves && held < n && std::abs(heading[held] - heading[execute]) >= turn) return execute;
    k = held;  // a shorter order: the hand steering before the test
  }
  return -1;
}

}  // namespace usvid
