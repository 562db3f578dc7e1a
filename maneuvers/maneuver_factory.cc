#include "maneuvers/maneuver_factory.h"

#include "core/error.h"
#include "maneuvers/autopilot.h"
#include "maneuvers/input_schedule.h"
#include "maneuvers/step_grid.h"
#include "maneuvers/turning.h"
#include "maneuvers/zigzag.h"

namespace usvid {
namespace {

// A spec's numbers and how it was written, for the forms below.
struct Args {
  const ManeuverSpec& spec;
  std::string text;  // as written, for messages

  bool Given() const { return !spec.numbers.empty(); }  // "name:" with no number does not parse
  // The numbers, `min` to `max` of them.
  const std::vector<double>& Numbers(size_t min, size_t max) const {
    const size_t n = spec.numbers.size();
    if (n < min || n > max)
      throw InputError("--maneuver '" + text + "': expected " + std::to_string(min) +
                       (max > min ? " to " + std::to_string(max) : "") + " number(s) after ':'");
    return spec.numbers;
  }
  double Positive(double value) const {
    if (!(value > 0)) throw InputError("--maneuver '" + text + "': the value must be positive");
    return value;
  }
  // The one positive number of a spec like random-steps:HOLD_S; `fallback` without one.
  double OnePositiveOr(double fallback) const {
    return Given() ? Positive(Numbers(1, 1)[0]) : fallback;
  }
};

// duration_s, or the maneuver's own `fallback` when 0.
double Duration(double duration_s, double fallback) {
  return duration_s > 0 ? duration_s : fallback;
}

// One row per maneuver: its name and numbers as a user writes them, and how its numbers make it.
// A maneuver's parameters are read here and nowhere else
// (docs/architecture.md#adding-a-maneuver-parameter).
struct ManeuverForm {
  ManeuverKind kind;
  const char* grammar;
  std::unique_ptr<Maneuver> (*make)(const Args&, const Actuation&, double duration_s,
                                    uint64_t seed);
};

constexpr ManeuverForm kForms[] = {
    {ManeuverKind::kZigzag, "zigzag[:A/B]",
     [](const Args& a, const Actuation& act, double duration_s, uint64_t) {
       const std::vector<double> ab =
           a.Given() ? a.Numbers(2, 2) : std::vector<double>{kDefaultZigzagDeg, kDefaultZigzagDeg};
       return std::unique_ptr<Maneuver>(std::make_unique<ZigZag>(
           act, ab[0], ab[1], Duration(duration_s, 300), a.spec.base_offset_rad));
     }},
    {ManeuverKind::kTurning, "turning[:A]",
     [](const Args& a, const Actuation& act, double duration_s, uint64_t) {
       const double angle = a.Given() ? a.Numbers(1, 1)[0] : kDefaultTurningDeg;
       return std::unique_ptr<Maneuver>(
           std::make_unique<Turning>(act, angle, Duration(duration_s, 300)));
     }},
    {ManeuverKind::kStepGrid, "stepgrid[:T/Y[/HOLD_S]]",
     [](const Args& a, const Actuation& act, double duration_s, uint64_t) {
       StepGridOptions opt;
       if (a.Given()) {
         // T/Y, or T/Y/H with a fixed hold of H seconds a step.
         const std::vector<double>& ty = a.Numbers(2, 3);
         opt.thrust_levels = static_cast<int>(ty[0]);
         opt.yaw_levels = static_cast<int>(ty[1]);
         if (ty.size() == 3) {
           if (!(ty[2] > 0))
             throw InputError("--maneuver '" + a.text + "': the hold must be positive");
           opt.hold_s = ty[2];
         }
       }
       return std::unique_ptr<Maneuver>(
           std::make_unique<StepGrid>(act, opt, Duration(duration_s, 3600)));
     }},
    {ManeuverKind::kRandomSteps, "random-steps[:HOLD_S]",
     [](const Args& a, const Actuation& act, double duration_s, uint64_t seed) {
       const double hold = a.OnePositiveOr(6.0);
       return MakeRandomSteps(act, hold, Duration(duration_s, 600), seed);
     }},
    {ManeuverKind::kPrbs, "prbs[:CLOCK_S]",
     [](const Args& a, const Actuation& act, double duration_s, uint64_t seed) {
       const double clock = a.OnePositiveOr(4.0);
       return MakePrbs(act, clock, Duration(duration_s, 600), seed);
     }},
    {ManeuverKind::kMultisine, "multisine[:FMAX_HZ]",
     [](const Args& a, const Actuation& act, double duration_s, uint64_t seed) {
       const double f_max = a.OnePositiveOr(0.2);
       return MakeMultisine(act, f_max, Duration(duration_s, 600), seed);
     }},
    {ManeuverKind::kAutopilot, "autopilot[:HOLD_S[/SPAN_DEG]]",
     [](const Args& a, const Actuation& act, double duration_s, uint64_t seed) {
       const std::vector<double> n = a.Given() ? a.Numbers(1, 2) : std::vector<double>{20.0};
       const double span = n.size() == 2 ? n[1] : Autopilot::kDefaultCourseSpanDeg;
       return std::unique_ptr<Maneuver>(std::make_unique<Autopilot>(
           act, a.Positive(n[0]), Duration(duration_s, 600), seed, span));
     }},
};

}  // namespace

std::string ManeuverGrammar() {
  std::string out;
  for (const ManeuverForm& f : kForms) out += (out.empty() ? "" : ", ") + std::string(f.grammar);
  return out;
}

std::unique_ptr<Maneuver> MakeManeuver(const std::string& spec, const Actuation& act,
                                       double duration_s, uint64_t seed) {
  return MakeManeuver(ParseManeuverSpec(spec), act, duration_s, seed);
}

std::unique_ptr<Maneuver> MakeManeuver(const ManeuverSpec& spec, const Actuation& act,
                                       double duration_s, uint64_t seed) {
  if (duration_s < 0) throw InputError("--duration: must not be negative");
  const Args args{spec, spec.Text()};
  for (const ManeuverForm& f : kForms)
    if (f.kind == spec.kind) return f.make(args, act, duration_s, seed);
  throw InputError("--maneuver '" + args.text + "': unknown maneuver (known: " + ManeuverGrammar() +
                   ")");
}

}  // namespace usvid
