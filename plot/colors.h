// Colours of usvid plots. Series take the Okabe-Ito palette (distinguishable with the common
// colour-vision deficiencies, and in greyscale by lightness); heat maps take viridis, a
// perceptually uniform sequential scale from dark purple (low) to yellow (high). Nothing here
// throws.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace usvid::svg {

// A colour with channels in [0, 1].
struct Rgb {
  double r = 0.0;
  double g = 0.0;
  double b = 0.0;
};

// "#rrggbb".
std::string Hex(const Rgb& color);

// The i-th series colour, cycling after kSeriesColorCount.
std::string_view SeriesColor(std::size_t index);
inline constexpr std::size_t kSeriesColorCount = 7;

// Viridis at t in [0, 1] (clamped; NaN reads as 0), interpolated between tabulated anchors.
Rgb Viridis(double t);

// WCAG relative luminance in [0, 1]; text on a fill is dark when this is above about 0.35.
double RelativeLuminance(const Rgb& color);

}  // namespace usvid::svg
