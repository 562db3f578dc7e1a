// LinePlot layout: margins from the text that surrounds the plot area, then nice ticks for the
// area that remains. The strip of band / reference-line labels above the area depends on the
// x mapping and the mapping on the margins, so the two are settled by a short fixed-point loop.
#include <algorithm>
#include <cmath>

#include "plot/colors.h"
#include "plot/line_plot_metrics.h"
#include "plot/svg_plot.h"
#include "plot/svg_text.h"

namespace usvid {
namespace {

using namespace line_plot_metrics;  // NOLINT(build/namespaces): the shared layout measures

constexpr double kAnnotationSpacing = 10.0;  // between labels of one row

// 2 % of the span added on both sides, so that data just below a tick do not touch the frame;
// a range that starts (or ends) at zero keeps that end.
std::pair<double, double> Headroom(std::pair<double, double> r) {
  const double pad = 0.02 * (r.second - r.first);
  return {r.first >= 0.0 ? std::max(0.0, r.first - pad) : r.first - pad,
          r.second <= 0.0 ? std::min(0.0, r.second + pad) : r.second + pad};
}

int YTickBudget(double area_height) {
  return std::clamp(static_cast<int>(area_height / kYTickSpacing) + 1, 2, 11);
}

// The most x ticks whose labels do not collide in `area_width`.
svg::AxisTicks XTicks(double lo, double hi, bool fixed, double area_width) {
  int budget = std::clamp(static_cast<int>(area_width / 50.0) + 1, 2, 16);
  for (;; --budget) {
    svg::AxisTicks t = fixed ? svg::FixedTicks(lo, hi, budget) : svg::NiceTicks(lo, hi, budget);
    const double spacing = area_width * t.step / (t.hi - t.lo);
    if (budget == 2 || svg::WidestLabel(t, kTickFont) + kXTickGap <= spacing) return t;
  }
}

}  // namespace

std::vector<svg::LegendEntry> LinePlot::LegendEntries() const {
  std::vector<svg::LegendEntry> entries;
  for (std::size_t i = 0; i < series_.size(); ++i) {
    entries.push_back({series_[i].name, StyleOf(i), ColorOf(i)});
  }
  return entries;
}

std::vector<LinePlot::AnnotationLabel> LinePlot::PlaceAnnotations(const svg::AxisTicks& x,
                                                                  double area_left,
                                                                  double area_width) const {
  const double scale = area_width / (x.hi - x.lo);
  const auto px = [&](double v) { return area_left + (v - x.lo) * scale; };
  std::vector<AnnotationLabel> labels;
  for (const Band& b : bands_) {
    const double lo = std::max(b.lo, x.lo);
    const double hi = std::min(b.hi, x.hi);
    if (!b.label.empty() && lo < hi) labels.push_back({0.5 * (px(lo) + px(hi)), b.label, 0});
  }
  for (const VerticalLine& l : lines_) {
    if (!l.label.empty() && l.x >= x.lo && l.x <= x.hi) labels.push_back({px(l.x), l.label, 0});
  }
  std::vector<std::vector<std::pair<double, double>>> rows;  // occupied intervals per row
  for (AnnotationLabel& label : labels) {
    const double half = 0.5 * svg::TextWidth(label.text, kAnnotationFont);
    // Kept above the plot area where it fits, so it does not run off the canvas.
    label.centre = std::clamp(label.centre, area_left + half,
                              std::max(area_left + half, area_left + area_width - half));
    const double a = label.centre - half - kAnnotationSpacing / 2.0;
    const double b = label.centre + half + kAnnotationSpacing / 2.0;
    std::size_t row = 0;
    for (; row < rows.size(); ++row) {
      const bool free = std::none_of(rows[row].begin(), rows[row].end(),
                                     [&](const auto& iv) { return a < iv.second && iv.first < b; });
      if (free) break;
    }
    if (row == rows.size()) rows.emplace_back();
    rows[row].push_back({a, b});
    label.row = static_cast<int>(row);
  }
  return labels;
}

LinePlotLayout LinePlot::Layout(double width, double height, const LayoutRequest& request) const {
  LinePlotLayout L;
  L.width = width;
  L.height = height;
  const std::vector<svg::LegendEntry> legend =
      request.legend ? LegendEntries() : std::vector<svg::LegendEntry>{};
  const double legend_width = svg::LegendColumnWidth(legend);
  const bool below = !legend.empty() && request.allow_legend_below &&
                     (legend_ == LegendPlacement::kBelow ||
                      (legend_ == LegendPlacement::kAuto && legend_width > 0.3 * width));
  L.legend_right = !legend.empty() && !below;

  const auto extent = request.x_extent ? request.x_extent : XExtent();
  const bool x_fixed = request.x_extent ? request.x_fixed : x_range_.has_value();
  const auto [x_lo, x_hi] = extent.value_or(std::pair{0.0, 1.0});
  const std::optional<std::pair<double, double>> y_data = YExtent(x_lo, x_hi);
  const auto [y_lo, y_hi] = y_range_ ? *y_range_ : y_data ? Headroom(*y_data) : std::pair{0.0, 1.0};

  const bool x_label = request.x_label && !x_label_.empty();
  double bottom = kPad + (request.x_tick_labels ? kTickGap + kTickFont : 0.0) +
                  (x_label ? kLabelGap + kLabelFont : 0.0);
  if (below) bottom += 10.0 + svg::LegendRowsHeight(legend, width - 2.0 * kPad);

  for (int iteration = 0; iteration < 4; ++iteration) {
    const double top = kPad + (title_.empty() ? 0.0 : request.title_font_size + 8.0) +
                       L.annotation_rows * kAnnotationRow + (L.annotation_rows > 0 ? 4.0 : 0.0);
    L.area_top = top;
    L.area_height = std::max(kMinArea, height - top - bottom);
    L.y = y_range_ ? svg::FixedTicks(y_lo, y_hi, YTickBudget(L.area_height))
                   : svg::NiceTicks(y_lo, y_hi, YTickBudget(L.area_height));
    L.area_left = std::max(request.min_left, kPad + (y_label_.empty() ? 0.0 : kLabelFont + 8.0) +
                                                 svg::WidestLabel(L.y, kTickFont) + kTickGap);
    // Room for half of the last x tick label, or for the legend column.
    const double right = std::max(request.min_right,
                                  L.legend_right ? kLegendGap + legend_width + kPad : kPad + 16.0);
    L.area_width = std::max(kMinArea, width - L.area_left - right);
    L.x = XTicks(x_lo, x_hi, x_fixed, L.area_width);
    int rows = 0;
    for (const AnnotationLabel& a : PlaceAnnotations(L.x, L.area_left, L.area_width)) {
      rows = std::max(rows, a.row + 1);
    }
    if (rows <= L.annotation_rows) break;
    L.annotation_rows = rows;
  }
  return L;
}

}  // namespace usvid
