#include "maneuvers/maneuver_factory.h"

#include "core/error.h"
#include "maneuvers/autopilot.h"
#include "maneuvers/input_schedule.h"
#include "maneuvers/maneuver_spec.h"
#include "maneuvers/step_grid.h"
#include "maneuvers/turning.h"
#include "maneuvers/zigzag.h"

namespace usvid {
namespace {

constexpr const char* kKnown =
    "zigzag:A/B, turning:A, stepgrid:T/Y[/HOLD_S], random-steps, prbs, multisine, autopilot:HOLD";

// The spec's numbers; `count` of them are expected.
std::vector<double> Numbers(const ManeuverSpec& parsed, size_t count, const std::string& spec) {
  if (parsed.numbers.size() != count)
    throw InputError("--maneuver '" + spec + "': expected " + std::to_string(count) +
                     " number(s) after ':'");
  return parsed.numbers;
}

double Positive(double value, const std::string& spec) {
  if (!(value > 0)) throw InputError("--maneuver '" + spec + "': the value must be positive");
  return value;
}

}  // namespace

std::unique_ptr<Maneuver> MakeManeuver(const std::string& spec, const Actuation& act,
                                       double duration_s, uint64_t seed) {
  return MakeManeuver(ParseManeuverSpec(spec), act, duration_s, seed);
}

std::unique_ptr<Maneuver> MakeManeuver(const ManeuverSpec& args, const Actuation& act,
                                       double duration_s, uint64_t seed) {
  if (duration_s < 0) throw InputError("--duration: must not be negative");
  const std::string spec = args.Text();
  const bool has_args = !args.numbers.empty();  // "name:" with no number does not parse
  auto duration = [&](double fallback) { return duration_s > 0 ? duration_s : fallback; };

  switch (args.kind) {
    case ManeuverKind::kZigzag: {
      const auto ab = has_args ? Numbers(args, 2, spec)
                               : std::vector<double>{kDefaultZigzagDeg, kDefaultZigzagDeg};
      return std::make_unique<ZigZag>(act, ab[0], ab[1], duration(300), args.base_offset_rad);
    }
    case ManeuverKind::kTurning: {
      const double a = has_args ? Numbers(args, 1, spec)[0] : kDefaultTurningDeg;
      return std::make_unique<Turning>(act, a, duration(300));
    }
    case ManeuverKind::kStepGrid: {
      StepGridOptions opt;
      if (has_args) {
        // T/Y, or T/Y/H with a fixed hold of H seconds a step.
        const auto ty = Numbers(args, args.numbers.size() == 3 ? 3 : 2, spec);
        opt.thrust_levels = static_cast<int>(ty[0]);
        opt.yaw_levels = static_cast<int>(ty[1]);
        if (ty.size() == 3) {
          if (!(ty[2] > 0))
            throw InputError("--maneuver '" + spec + "': the hold must be positive");
          opt.hold_s = ty[2];
        }
      }
      return std::make_unique<StepGrid>(act, opt, duration(3600));
    }
    case ManeuverKind::kRandomSteps: {
      const double hold = has_args ? Positive(Numbers(args, 1, spec)[0], spec) : 6.0;
      return MakeRandomSteps(act, hold, duration(600), seed);
    }
    case ManeuverKind::kPrbs: {
      const double clock = has_args ? Positive(Numbers(args, 1, spec)[0], spec) : 4.0;
      return MakePrbs(act, clock, duration(600), seed);
    }
    case ManeuverKind::kMultisine: {
      const double f_max = has_args ? Positive(Numbers(args, 1, spec)[0], spec) : 0.2;
      return MakeMultisine(act, f_max, duration(600), seed);
    }
    case ManeuverKind::kAutopilot: {
      const double hold = has_args ? Positive(Numbers(args, 1, spec)[0], spec) : 20.0;
      return std::make_unique<Autopilot>(act, hold, duration(600), seed);
    }
    case ManeuverKind::kUnknown:
      break;
  }
  throw InputError("--maneuver '" + spec + "': unknown maneuver (known: " + kKnown + ")");
}

}  // namespace usvid
