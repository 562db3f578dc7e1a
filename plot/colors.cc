#include "plot/colors.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace usvid::svg {
namespace {

// Okabe & Ito (2008) without yellow, which is unreadable as a thin line on white.
constexpr std::array<std::string_view, kSeriesColorCount> kSeries = {
    "#0072B2",  // blue
    "#D55E00",  // vermillion
    "#009E73",  // bluish green
    "#CC79A7",  // reddish purple
    "#E69F00",  // orange
    "#56B4E9",  // sky blue
    "#000000",  // black
};

// matplotlib's viridis sampled at t = 0, 0.1, ..., 1.
constexpr std::array<Rgb, 11> kViridis = {{
    {0.267004, 0.004874, 0.329415},
    {0.282623, 0.140926, 0.457517},
    {0.253935, 0.265254, 0.529983},
    {0.206756, 0.371758, 0.553117},
    {0.163625, 0.471133, 0.558148},
    {0.127568, 0.566949, 0.550556},
    {0.134692, 0.658636, 0.517649},
    {0.266941, 0.748751, 0.440573},
    {0.477504, 0.821444, 0.318195},
    {0.741388, 0.873449, 0.149561},
    {0.993248, 0.906157, 0.143936},
}};

double Linearize(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

}  // namespace

std::string Hex(const Rgb& color) {
  const auto byte = [](double c) {
    return static_cast<int>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
  };
  char buf[8];
  std::snprintf(buf, sizeof(buf), "#%02x%02x%02x", byte(color.r), byte(color.g), byte(color.b));
  return buf;
}

std::string_view SeriesColor(std::size_t index) { return kSeries[index % kSeries.size()]; }

Rgb Viridis(double t) {
  if (std::isnan(t)) t = 0.0;
  const double s = std::clamp(t, 0.0, 1.0) * static_cast<double>(kViridis.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(s), kViridis.size() - 2);
  const double f = s - static_cast<double>(i);
  const Rgb& a = kViridis[i];
  const Rgb& b = kViridis[i + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

double RelativeLuminance(const Rgb& color) {
  return 0.2126 * Linearize(color.r) + 0.7152 * Linearize(color.g) + 0.0722 * Linearize(color.b);
}

}  // namespace usvid::svg
