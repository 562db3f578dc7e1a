// Axis limits and tick marks at "nice" numbers: steps of 1, 2 or 5 times a power of ten, and
// compact tick labels ("0.25", "−3", "1.5e6"; negative numbers take the typographic minus
// U+2212). Callers pass finite limits; a zero-width range is widened around its value. Nothing
// here throws.
#pragma once

#include <string>
#include <vector>

namespace usvid::svg {

struct AxisTicks {
  double lo = 0.0;  // axis limits drawn at the plot-area edges
  double hi = 1.0;
  double step = 0.2;
  std::vector<double> values;       // tick positions in [lo, hi], ascending
  std::vector<std::string> labels;  // one per value
};

// Limits rounded out to the coarsest-needed step so that [data_lo, data_hi] is covered with at
// most `max_ticks` ticks (at least 2, or 3 when the range spans zero), the limits themselves
// being ticks.
AxisTicks NiceTicks(double data_lo, double data_hi, int max_ticks);

// Ticks at nice multiples inside the fixed limits [lo, hi], at most `max_ticks` of them.
AxisTicks FixedTicks(double lo, double hi, int max_ticks);

// `value` printed with just the decimals that a tick spacing of `step` needs; in scientific
// notation when the largest magnitude on the axis, `axis_magnitude`, is 1e6 or more or below 1e-3.
std::string FormatTick(double value, double step, double axis_magnitude);

// The widest label of `ticks` at `font_size` [px] (see TextWidth).
double WidestLabel(const AxisTicks& ticks, double font_size);

}  // namespace usvid::svg
