#include "simulation/wind_gusts.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/error.h"
#include "core/parse_number.h"
#include "simulation/wind_estimates.h"

namespace usvid {
namespace {

constexpr double kDefaultLengthM = 10.0;
constexpr double kGust = 0.3;

double Number(const std::string& text, const std::string& where) {
  const ParsedNumber p = ParseNumber(text);
  if (p.status != NumberStatus::kOk)
    throw InputError(where + ": " + DescribeNumberStatus(p.status, text));
  return p.value;
}

// The parameter called `name`, or NaN.
double Param(const VesselInfo& info, const std::string& name) {
  const auto it = std::find(info.params.begin(), info.params.end(), name);
  return it == info.params.end() ? NAN : info.default_params[it - info.params.begin()];
}

}  // namespace

WindGusts MakeWindGusts(const VesselInfo& info, const std::string& spec, uint64_t seed,
                        const std::string& where) {
  WindGusts g;
  const auto colon = spec.find(':');
  g.wind.speed = Number(spec.substr(0, colon), where);
  if (!(g.wind.speed >= 0.0 && g.wind.speed <= 40.0))
    throw InputError(where + ": the mean wind speed must be in [0, 40] m/s");
  if (colon != std::string::npos) {
    g.wind.from_rad = Number(spec.substr(colon + 1), where) * std::numbers::pi / 180.0;
  } else {
    std::mt19937_64 rng(seed ^ 0x6057ull);
    g.wind.from_rad = std::uniform_real_distribution<double>(0.0, 2 * std::numbers::pi)(rng);
  }
  g.wind.gust = kGust;
  g.heading = info.StateIndex("psi");
  g.surge = info.StateIndex("u");
  g.sway = info.StateIndex("v");
  if (g.heading < 0 || g.surge < 0 || g.sway < 0 || info.StateIndex("r") < 0)
    throw InputError(where + ": vessel " + info.name +
                     " has no psi, u, v and r for a wind to act on");
  if (const double m11 = Param(info, "m11"); std::isfinite(m11)) {
    g.inertia = {m11, Param(info, "m22"), Param(info, "m33")};
  } else if (const double m = Param(info, "m"); std::isfinite(m)) {
    auto added = [&](const char* name) {
      const double a = Param(info, name);
      return std::isfinite(a) ? a : 0.0;
    };
    g.inertia = {m + added("Xud"), m + added("Yvd"), Param(info, "Iz") + added("Nrd")};
  }
  if (!(g.inertia[0] > 0 && g.inertia[1] > 0 && g.inertia[2] > 0))
    throw InputError(where + ": vessel " + info.name +
                     " names no mass and inertia (m11, m22, m33, or m and Iz); a vessel file "
                     "with a wind section logs its wind instead (--wind)");
  WindBody body;
  body.L = info.length_m > 0 ? info.length_m : kDefaultLengthM;
  body.B = body.L / 3.0;
  const double h = 0.12 * body.L;
  body.A_L = body.L * h;
  body.A_T = 1.2 * body.B * h;
  body.A_OD = 0.3 * body.A_L;
  body.H_BR = 0.25 * body.L;
  body.H_C = 0.5 * h;
  const std::vector<MmgEstimate> estimates = EstimateWindCoefficients(body);
  for (size_t i = 0; i < g.coefficients.size() && i < estimates.size(); ++i)
    g.coefficients[i] = estimates[i].value;
  g.areas = {1.22, body.A_T, body.A_L, body.L};
  return g;
}

std::function<std::array<double, 3>(double, std::span<const double>)> GustDisturbance(
    const WindGusts& gusts, uint64_t seed) {
  const GustySpeed speed(gusts.wind, seed);
  return [gusts, speed](double t, std::span<const double> x) {
    const std::array<double, 2> rel = RelativeWind(speed(t), gusts.wind.from_rad, x[gusts.heading],
                                                   x[gusts.surge], x[gusts.sway]);
    std::array<double, 3> f{};
    AddWindForce(rel[0], rel[1], gusts.coefficients.data(), gusts.areas, 1.0, f.data());
    return std::array<double, 3>{f[0] / gusts.inertia[0], f[1] / gusts.inertia[1],
                                 f[2] / gusts.inertia[2]};
  };
}

nlohmann::json WindGustsToJson(const WindGusts& gusts) {
  return {{"speed", gusts.wind.speed}, {"from_deg", gusts.wind.from_rad * 180.0 / std::numbers::pi},
          {"gust", gusts.wind.gust},   {"A_T", gusts.areas.A_T},
          {"A_L", gusts.areas.A_L},    {"L", gusts.areas.L},
          {"measured", false}};
}

}  // namespace usvid
