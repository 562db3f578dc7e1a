// A maneuver under a true wind: its measured wind inputs (InputRole::kMeasured: wind_speed,
// wind_direction) set to the relative wind that an anemometer aboard reads, from the true wind
// and the vessel's heading and velocity at each command. `usvid simulate --wind` uses it to make
// a record with wind for the effect `wind` to hide in (docs/data.md#effects).
//   true wind   from `from_rad` (clockwise from north), speed W(t) = W (1 + gust g(t)), g a sum
//               of six sines of 0.01-0.2 Hz with random phases from the seed, |g| <= 1
//   relative    the air's velocity over the hull, a = R(psi)^T w - [u, v]: wind_speed = |a|,
//               wind_direction = atan2(-a_v, -a_u) in [0, 2 pi), where it blows from,
//               clockwise from the bow (simulators/wind_force.h)
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "maneuvers/maneuver.h"

namespace usvid {

struct TrueWind {
  double speed = 0.0;     // [m/s] mean
  double from_rad = 0.0;  // where it blows from, clockwise from north
  double gust = 0.2;      // the gusts' largest fraction of the mean speed
};

// The true wind's speed over time: W (1 + gust g(t)), g the mean of six sines of 0.01-0.2 Hz
// (log-spaced) with phases drawn from the seed, so |g| <= 1.
class GustySpeed {
 public:
  GustySpeed(const TrueWind& wind, uint64_t seed);
  double operator()(double t) const;

 private:
  static constexpr int kSines = 6;
  TrueWind wind_;
  std::array<double, kSines> frequency_{}, phase_{};
};

// The relative wind [speed, direction] over a hull heading psi with body velocities u, v.
std::array<double, 2> RelativeWind(double true_speed, double true_from_rad, double psi, double u,
                                   double v);

// The same from the air's velocity over the ground [north, east] (m/s; where it blows to).
std::array<double, 2> RelativeWindOf(const std::array<double, 2>& air, double psi, double u,
                                     double v);

// The inverse: the air's velocity over the ground [north, east] from the relative wind an
// anemometer aboard reads (speed, where it blows from, clockwise from the bow) on a hull heading
// psi with body velocities u, v. What a log's relative wind says of the true wind.
std::array<double, 2> AirOverGround(double relative_speed, double relative_from_rad, double psi,
                                    double u, double v);

// `inner` with its measured wind inputs from `wind`. InputError for a vessel without wind inputs
// or without a heading and surge-sway states.
std::unique_ptr<Maneuver> UnderTrueWind(std::unique_ptr<Maneuver> inner, const Actuation& act,
                                        const TrueWind& wind, uint64_t seed);

}  // namespace usvid
