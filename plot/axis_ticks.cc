#include "plot/axis_ticks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "plot/svg_text.h"

namespace usvid::svg {
namespace {

constexpr double kTolerance = 1e-9;  // in units of one step
constexpr std::array<int, 3> kMantissas = {1, 2, 5};

// A 1-2-5 step: mantissa * 10^exponent, with k * step computed exactly where possible.
struct Step {
  int mantissa;
  int exponent;
  double Value() const { return Times(1.0); }
  double Times(double k) const {
    return exponent >= 0 ? k * mantissa * std::pow(10.0, exponent)
                         : k * mantissa / std::pow(10.0, -exponent);
  }
};

// Keeps the span finite and widens a range that is degenerate (or below double resolution)
// around its centre.
void Widen(double& lo, double& hi) {
  constexpr double kHuge = 1e300;
  lo = std::clamp(lo, -kHuge, kHuge);
  hi = std::clamp(hi, -kHuge, kHuge);
  const double magnitude = std::max(std::abs(lo), std::abs(hi));
  if (hi - lo > magnitude * 1e-12) return;
  const double centre = 0.5 * (lo + hi);
  const double half = centre == 0.0 ? 1.0 : std::abs(centre) * 0.1;
  lo = centre - half;
  hi = centre + half;
}

// Steps from fine to coarse, starting well below span / max_ticks.
template <typename Accept>
Step FirstStep(double span, int max_ticks, Accept accept) {
  int exponent = static_cast<int>(std::floor(std::log10(span / max_ticks))) - 1;
  for (;; ++exponent) {
    for (const int m : kMantissas) {
      const Step step{m, exponent};
      if (accept(step)) return step;
    }
  }
}

void Label(AxisTicks& ticks) {
  if (ticks.values.empty()) ticks.values = {ticks.lo, ticks.hi};
  const double magnitude = std::max(std::abs(ticks.values.front()), std::abs(ticks.values.back()));
  ticks.labels.clear();
  for (const double v : ticks.values) ticks.labels.push_back(FormatTick(v, ticks.step, magnitude));
}

}  // namespace

AxisTicks NiceTicks(double data_lo, double data_hi, int max_ticks) {
  Widen(data_lo, data_hi);
  // Limits on both sides of zero need three ticks at least (-s, 0, s).
  max_ticks = std::max(max_ticks, data_lo < 0.0 && data_hi > 0.0 ? 3 : 2);
  long k_lo = 0;
  long k_hi = 0;
  const Step step = FirstStep(data_hi - data_lo, max_ticks, [&](const Step& s) {
    k_lo = std::lround(std::floor(data_lo / s.Value() + kTolerance));
    k_hi = std::lround(std::ceil(data_hi / s.Value() - kTolerance));
    return k_hi - k_lo + 1 <= max_ticks && k_hi > k_lo;
  });
  AxisTicks ticks;
  ticks.step = step.Value();
  for (long k = k_lo; k <= k_hi; ++k) ticks.values.push_back(step.Times(static_cast<double>(k)));
  ticks.lo = ticks.values.front();
  ticks.hi = ticks.values.back();
  Label(ticks);
  return ticks;
}

AxisTicks FixedTicks(double lo, double hi, int max_ticks) {
  max_ticks = std::max(max_ticks, 2);
  Widen(lo, hi);
  long k_lo = 0;
  long k_hi = 0;
  const Step step = FirstStep(hi - lo, max_ticks, [&](const Step& s) {
    k_lo = std::lround(std::ceil(lo / s.Value() - kTolerance));
    k_hi = std::lround(std::floor(hi / s.Value() + kTolerance));
    return k_hi - k_lo + 1 <= max_ticks;
  });
  AxisTicks ticks;
  ticks.lo = lo;
  ticks.hi = hi;
  ticks.step = step.Value();
  for (long k = k_lo; k <= k_hi; ++k) ticks.values.push_back(step.Times(static_cast<double>(k)));
  Label(ticks);
  return ticks;
}

std::string FormatTick(double value, double step, double axis_magnitude) {
  if (std::abs(value) < std::abs(step) * kTolerance * 1e3) return "0";
  char buf[64];
  if (axis_magnitude >= 1e6 || axis_magnitude < 1e-3) {
    const int exponent = static_cast<int>(std::floor(std::log10(std::abs(value)) + kTolerance));
    const int decimals =
        std::max(0, exponent - static_cast<int>(std::floor(std::log10(step) + kTolerance)));
    std::snprintf(buf, sizeof(buf), "%.*fe%d", decimals, value / std::pow(10.0, exponent),
                  exponent);
  } else {
    const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + kTolerance)));
    std::snprintf(buf, sizeof(buf), "%.*f", decimals, value);
  }
  std::string s = buf;
  if (s.front() == '-') s.replace(0, 1, "\u2212");
  return s;
}

double WidestLabel(const AxisTicks& ticks, double font_size) {
  double widest = 0.0;
  for (const std::string& label : ticks.labels) {
    widest = std::max(widest, TextWidth(label, font_size));
  }
  return widest;
}

}  // namespace usvid::svg
