#include "design/optimize.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <nlopt.hpp>
#include <vector>

#include "simulation/vessel_simulator.h"

namespace usvid::design {
namespace {

struct Knobs {
  std::vector<double> lo, hi;
};

std::optional<Knobs> KnobsOf(const std::string& family, const VesselInfo& info) {
  if (family == "zigzag") {
    const double full = info.actuation.yaw_is_angle ? info.actuation.yaw_full_deg : 35.0;
    return Knobs{{5.0, 5.0}, {std::max(5.5, full), 40.0}};
  }
  if (family == "random-steps") return Knobs{{1.0}, {60.0}};
  if (family == "prbs") return Knobs{{0.5}, {30.0}};
  if (family == "multisine") return Knobs{{0.02}, {1.0}};
  return std::nullopt;
}

std::string Spec(const std::string& family, const std::vector<double>& x) {
  std::string spec = family + ":";
  for (size_t i = 0; i < x.size(); ++i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x[i]);
    spec += (i > 0 ? "/" : "") + std::string(buf);
  }
  return spec;
}

}  // namespace

std::optional<ManeuverInformation> OptimizeManeuver(const std::string& vessel,
                                                    const std::string& method,
                                                    const std::string& family, double seconds,
                                                    const NoiseModel& noise, int evaluations) {
  const std::string name = family.substr(0, family.find(':'));
  const auto knobs = KnobsOf(name, FindVessel(vessel).Info());
  if (!knobs) return std::nullopt;
  auto objective = [&](const std::vector<double>& x) {
    try {
      const double v = InformationOf(vessel, method, Spec(name, x), seconds, noise).log_det;
      return std::isfinite(v) ? v : -1e300;
    } catch (const std::exception&) {
      return -1e300;  // a design that cannot be simulated
    }
  };
  nlopt::opt opt(nlopt::GN_DIRECT_L, static_cast<unsigned>(knobs->lo.size()));
  opt.set_lower_bounds(knobs->lo);
  opt.set_upper_bounds(knobs->hi);
  opt.set_maxeval(evaluations * static_cast<int>(knobs->lo.size()));
  opt.set_max_objective(
      [](const std::vector<double>& x, std::vector<double>&, void* data) {
        return (*static_cast<decltype(objective)*>(data))(x);
      },
      &objective);
  std::vector<double> x(knobs->lo.size());
  for (size_t i = 0; i < x.size(); ++i) x[i] = 0.5 * (knobs->lo[i] + knobs->hi[i]);
  double best = -std::numeric_limits<double>::infinity();
  try {
    opt.optimize(x, best);
  } catch (const nlopt::roundoff_limited&) {
    // DIRECT-L stopped on round-off: x holds the best point found.
  }
  return InformationOf(vessel, method, Spec(name, x), seconds, noise);
}

}  // namespace usvid::design
