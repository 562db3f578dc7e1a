#include "design/optimize.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <nlopt.hpp>
#include <vector>

#include "maneuvers/maneuver_spec.h"
#include "simulation/vessel_simulator.h"

namespace usvid::design {
namespace {

struct Knobs {
  std::vector<double> lo, hi;
  bool integer = false;  // counts: each point is rounded to whole numbers
};

std::optional<Knobs> KnobsOf(ManeuverKind family, const VesselInfo& info) {
  switch (family) {
    case ManeuverKind::kZigzag: {
      const double full = info.actuation.yaw_is_angle ? info.actuation.yaw_full_deg : 35.0;
      return Knobs{{5.0, 5.0}, {std::max(5.5, full), 40.0}};
    }
    case ManeuverKind::kStepGrid:
      return Knobs{{2.0, 1.0}, {8.0, 5.0}, true};
    case ManeuverKind::kRandomSteps:
      return Knobs{{1.0}, {60.0}};
    case ManeuverKind::kPrbs:
      return Knobs{{0.5}, {30.0}};
    case ManeuverKind::kMultisine:
      return Knobs{{0.02}, {1.0}};
    default:
      return std::nullopt;
  }
}

std::string Spec(const std::string& family, const std::vector<double>& x, bool integer) {
  std::string spec = family + ":";
  for (size_t i = 0; i < x.size(); ++i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", integer ? std::round(x[i]) : x[i]);
    spec += (i > 0 ? "/" : "") + std::string(buf);
  }
  return spec;
}

}  // namespace

std::optional<ManeuverInformation> OptimizeManeuver(const DesignProblem& problem,
                                                    const std::string& family, int evaluations) {
  const ManeuverSpec parsed = ParseManeuverSpec(family);
  const std::string& name = parsed.name;
  const auto knobs = KnobsOf(parsed.kind, problem.vessel.Info());
  if (!knobs) return std::nullopt;
  auto objective = [&](const std::vector<double>& x) {
    try {
      const ManeuverInformation m = InformationOf(problem, Spec(name, x, knobs->integer));
      return std::isfinite(m.log_det) && m.unusable.empty() ? m.log_det : -1e300;
    } catch (const std::exception&) {
      return -1e300;  // a design that cannot be simulated
    }
  };
  nlopt::opt opt(nlopt::GN_DIRECT_L, static_cast<unsigned>(knobs->lo.size()));
  opt.set_lower_bounds(knobs->lo);
  opt.set_upper_bounds(knobs->hi);
  opt.set_maxeval(evaluations * static_cast<int>(knobs->lo.size()));
  opt.set_max_objective([](const std::vector<double>& x, std::vector<double>&,
                           void* data) { return (*static_cast<decltype(objective)*>(data))(x); },
                        &objective);
  std::vector<double> x(knobs->lo.size());
  for (size_t i = 0; i < x.size(); ++i) x[i] = 0.5 * (knobs->lo[i] + knobs->hi[i]);
  double best = -std::numeric_limits<double>::infinity();
  try {
    opt.optimize(x, best);
  } catch (const nlopt::roundoff_limited&) {
    // DIRECT-L stopped on round-off: x holds the best point found.
  }
  return InformationOf(problem, Spec(name, x, knobs->integer));
}

}  // namespace usvid::design
