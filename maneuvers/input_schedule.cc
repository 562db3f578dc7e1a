#include "maneuvers/input_schedule.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "maneuvers/excitation.h"
#include "maneuvers/steps.h"

namespace usvid {
namespace {

bool Excited(const Actuation& act, int i) {
  return act.roles[i] != InputRole::kFixed && act.roles[i] != InputRole::kMeasured;
}

// A stream per input, derived from the seed, so inputs do not share randomness.
std::mt19937_64 StreamFor(uint64_t seed, uint64_t salt, int input) {
  std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32),
                    static_cast<uint32_t>(salt), static_cast<uint32_t>(input)};
  return std::mt19937_64(seq);
}

// The schedule holding each excited input at its steps, the others at cruise.
std::unique_ptr<Maneuver> StepSchedule(const std::string& spec, const Actuation& act,
                                       double duration_s, std::vector<Steps> steps) {
  const std::vector<double> initial = CruiseCommand(act);
  auto command = [act, steps = std::move(steps), initial](double t, std::span<double> u) {
    for (int i = 0; i < act.inputs(); ++i) u[i] = Excited(act, i) ? steps[i].At(t) : initial[i];
  };
  return std::make_unique<InputSchedule>(spec, duration_s, act.inputs(), command);
}

}  // namespace

std::unique_ptr<Maneuver> MakeRandomSteps(const Actuation& act, double hold_s, double duration_s,
                                          uint64_t seed) {
  std::vector<Steps> steps(act.inputs());
  for (int i = 0; i < act.inputs(); ++i) {
    if (!Excited(act, i)) continue;
    auto rng = StreamFor(seed, 0x5EED, i);
    const auto [lo, hi] = ExcitationRange(act, i);
    const double hold = act.roles[i] == InputRole::kThrust ? 4 * hold_s : hold_s;
    steps[i] = Steps::Random(lo, hi, 0.5 * hold, 1.5 * hold, duration_s, rng);
  }
  return StepSchedule("random-steps", act, duration_s, std::move(steps));
}

std::unique_ptr<Maneuver> MakePrbs(const Actuation& act, double clock_s, double duration_s,
                                   uint64_t seed) {
  std::vector<Steps> steps(act.inputs());
  for (int i = 0; i < act.inputs(); ++i) {
    if (!Excited(act, i)) continue;
    auto rng = StreamFor(seed, 0xB125, i);
    uint32_t lfsr = 1 + static_cast<uint32_t>(rng() % 1023);  // any non-zero 10-bit state
    const auto [lo, hi] = ExcitationRange(act, i);
    const double low = lo + 0.15 * (hi - lo), high = lo + 0.85 * (hi - lo);
    const double clock = act.roles[i] == InputRole::kThrust ? 5 * clock_s : clock_s;
    for (double t = 0; t < duration_s; t += clock) {
      // x^10 + x^7 + 1: taps 10 and 7, period 1023.
      const uint32_t bit = ((lfsr >> 9) ^ (lfsr >> 6)) & 1u;
      lfsr = ((lfsr << 1) | bit) & 0x3FFu;
      steps[i].times.push_back(t);
      steps[i].levels.push_back(bit ? high : low);
    }
  }
  return StepSchedule("prbs", act, duration_s, std::move(steps));
}

std::unique_ptr<Maneuver> MakeMultisine(const Actuation& act, double f_max_hz, double duration_s,
                                        uint64_t seed) {
  struct Sines {
    std::vector<double> omega, phase;
    double center = 0.0, scale = 0.0;
  };
  std::vector<Sines> sines(act.inputs());
  const double f0 = 1.0 / duration_s;
  for (int i = 0; i < act.inputs(); ++i) {
    if (!Excited(act, i)) continue;
    auto rng = StreamFor(seed, 0x5105, i);
    std::uniform_real_distribution<double> phase(0.0, 2 * std::numbers::pi);
    const double f_max = act.roles[i] == InputRole::kThrust ? f_max_hz / 10 : f_max_hz;
    Sines& s = sines[i];
    for (int k = 1; k * f0 <= f_max || k == 1; ++k) {
      s.omega.push_back(2 * std::numbers::pi * k * f0);
      s.phase.push_back(phase(rng));
    }
    // Scale to the peak over a fine grid so the signal spans 90 % of the range.
    double peak = 0.0;
    for (double t = 0; t < duration_s; t += 0.05) {
      double y = 0.0;
      for (size_t k = 0; k < s.omega.size(); ++k) y += std::sin(s.omega[k] * t + s.phase[k]);
      peak = std::max(peak, std::abs(y));
    }
    const auto [lo, hi] = ExcitationRange(act, i);
    s.center = 0.5 * (lo + hi);
    s.scale = peak > 0 ? 0.45 * (hi - lo) / peak : 0.0;
  }
  const std::vector<double> initial = CruiseCommand(act);
  auto command = [act, sines, initial](double t, std::span<double> u) {
    for (int i = 0; i < act.inputs(); ++i) {
      if (!Excited(act, i)) {
        u[i] = initial[i];
        continue;
      }
      const Sines& s = sines[i];
      double y = 0.0;
      for (size_t k = 0; k < s.omega.size(); ++k) y += std::sin(s.omega[k] * t + s.phase[k]);
      u[i] = s.center + s.scale * y;
    }
  };
  return std::make_unique<InputSchedule>("multisine", duration_s, act.inputs(), command);
}

}  // namespace usvid
