// Turns a series into the polylines that are drawn. Non-finite points (NaN = not sampled) end
// a polyline, so gaps stay gaps. Within each polyline, consecutive points that fall into the
// same pixel column are reduced to the first, lowest, highest and last of them (in their
// original order): a 100 000-sample log on a 1000 px wide plot draws at most about 4000
// points, and single-sample spikes stay visible. Nothing here throws.
#pragma once

#include <span>
#include <vector>

namespace usvid::svg {

// Data -> pixel map of one axis: pixel = offset + scale * value.
struct AxisMap {
  double offset = 0.0;
  double scale = 1.0;
  double operator()(double value) const { return offset + scale * value; }
};

struct PixelPoint {
  double x = 0.0;
  double y = 0.0;
};

using Polyline = std::vector<PixelPoint>;

// `x` and `y` have equal lengths (the caller checks). Pixel coordinates are limited to
// [-kPixelLimit, kPixelLimit] so that far-off values do not produce absurd SVG numbers.
std::vector<Polyline> ToPolylines(std::span<const double> x, std::span<const double> y,
                                  const AxisMap& to_px_x, const AxisMap& to_px_y);

inline constexpr double kPixelLimit = 1e5;

}  // namespace usvid::svg
