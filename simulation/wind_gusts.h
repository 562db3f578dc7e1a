// An unmeasured, gusty wind on a vessel that logs no wind: the disturbance of the realistic
// suite (docs/compare.md#realistic). The true wind (maneuvers/true_wind.h: mean speed, where it
// blows from, gusts of 0.01-0.2 Hz up to `gust` of the mean) meets the hull in its state at
// every control period; its force and moment come from Fujiwara, Ueno & Nimura's coefficients
// (simulators/wind_force.h), estimated (simulation/wind_estimates.h) for a small craft's body
// above the water scaled from the hull length L (the vessel's, else 10 m):
//   breadth L / 3; mean height above water h = 0.12 L; A_L = L h; A_T = 1.2 (L / 3) h;
//   superstructure A_OD = 0.3 A_L, its top at 0.25 L, centred amidships
// (an 11 m craft: A_L 14.5 m^2, A_T 5.8 m^2). Fujiwara's regression is over merchant ships, so on
// a small craft it gives the order of the wind's force, not its exact value. The force becomes
// accelerations through the vessel's inertia with added mass: m11, m22, m33 where it has them
// (odin3dof), else m + Xud, m + Yvd, Iz + Nrd (odin-hs). The wind is in no channel of the
// record: a method sees its effect only.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "maneuvers/true_wind.h"
#include "simulation/vessel_simulator.h"
#include "simulators/wind_force.h"

namespace usvid {

struct WindGusts {
  TrueWind wind;
  WindAreas areas;
  std::array<double, WindCoefficients::kCount> coefficients{};
  std::array<double, 3> inertia{};  // [kg, kg, kg m^2] surge, sway, yaw, added mass included
  int heading = -1, surge = -1, sway = -1;  // state indices of psi, u, v
};

// "SPEED[:FROM_DEG]" (`--gusts`, a suite's "gusts"): a mean true wind of SPEED m/s in [0, 40],
// from FROM_DEG (default drawn from the seed), gusts up to 30 % of the mean. InputError naming
// `where` for a bad spec, or a vessel without psi, u, v and a mass and inertia it can name.
WindGusts MakeWindGusts(const VesselInfo& info, const std::string& spec, uint64_t seed,
                        const std::string& where);

// The disturbance for RunOptions::disturbance: accelerations [surge, sway, yaw rate].
std::function<std::array<double, 3>(double, std::span<const double>)> GustDisturbance(
    const WindGusts& gusts, uint64_t seed);

nlohmann::json WindGustsToJson(const WindGusts& gusts);

}  // namespace usvid
