#include "plot/decimate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace usvid::svg {
namespace {

// The run of consecutive points in one pixel column, by index into the polyline's points.
struct ColumnRun {
  std::size_t first = 0;
  std::size_t lowest = 0;
  std::size_t highest = 0;
  std::size_t last = 0;
};

void Flush(const ColumnRun& run, const std::vector<PixelPoint>& points, Polyline& out) {
  std::array<std::size_t, 4> keep = {run.first, run.lowest, run.highest, run.last};
  std::sort(keep.begin(), keep.end());
  const auto end = std::unique(keep.begin(), keep.end());
  for (auto it = keep.begin(); it != end; ++it) out.push_back(points[*it]);
}

// Reduces one run of finite points, already in pixels.
Polyline Reduce(const std::vector<PixelPoint>& points) {
  Polyline out;
  ColumnRun run;
  double column = std::floor(points[0].x);
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double c = std::floor(points[i].x);
    if (c != column) {
      Flush(run, points, out);
      run = {i, i, i, i};
      column = c;
      continue;
    }
    // Pixel y grows downwards: the lowest value has the largest pixel y.
    if (points[i].y > points[run.lowest].y) run.lowest = i;
    if (points[i].y < points[run.highest].y) run.highest = i;
    run.last = i;
  }
  Flush(run, points, out);
  return out;
}

double Limit(double px) { return std::clamp(px, -kPixelLimit, kPixelLimit); }

}  // namespace

std::vector<Polyline> ToPolylines(std::span<const double> x, std::span<const double> y,
                                  const AxisMap& to_px_x, const AxisMap& to_px_y) {
  std::vector<Polyline> lines;
  std::vector<PixelPoint> run;
  const auto close_run = [&] {
    if (!run.empty()) lines.push_back(Reduce(run));
    run.clear();
  };
  const std::size_t n = std::min(x.size(), y.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
      close_run();
      continue;
    }
    run.push_back({Limit(to_px_x(x[i])), Limit(to_px_y(y[i]))});
  }
  close_run();
  return lines;
}

}  // namespace usvid::svg
