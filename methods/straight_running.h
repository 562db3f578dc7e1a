// Straight running, the condition about which a vessel's manoeuvring equations are written, and
// where every hull damps each of its own motions: X_u, Y_v and N_r are below zero (resistance
// grows with speed, the hull resists a drift and a turn); a hull that is unstable on a course is
// so through the coupling of sway and yaw, not through these. An equation damped only through
// another state is not damped there: u' = c - k |v u| damps the surge while the ship drifts, but
// running straight its speed grows without bound. Averaged over a zig-zag, where |v| is seldom
// near zero, its d(u')/du is below zero all the same (GP's surge on a simulated KVLCC2 zig-zag
// with 2 % noise, docs/real-data.md#kvlcc2-transfer).
//
// At straight running every channel that a port-starboard mirror turns over is zero: the sway and
// yaw velocities, the rudder's or nozzle's angle, the lateral force and yaw moment, the lateral
// components of the wind and the current, the roll. Every other channel is at its median over
// the record. A state's own damping is read there with the state itself at its median, or, for a
// state the mirror turns over, at plus and minus its RMS: damping that grows with the motion
// (|v| v) vanishes at zero but not at the motion's size.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace usvid {

bool MirrorTurnsOver(std::string_view channel);

// A channel's median and RMS over its samples.
struct ChannelLevel {
  double median = 0.0, rms = 0.0;
};
ChannelLevel LevelOf(std::vector<double> samples);

// The points at which `names[state]`'s damping is read, as above: each a value per name; two
// for a state the mirror turns over, else one.
std::vector<std::vector<double>> StraightRunningPoints(const std::vector<std::string>& names,
                                                       const std::vector<ChannelLevel>& levels,
                                                       size_t state);

}  // namespace usvid
