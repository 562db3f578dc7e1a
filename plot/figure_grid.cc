#include "plot/figure_grid.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/atomic_file.h"
#include "core/error.h"
#include "plot/legend.h"
#include "plot/svg_text.h"

namespace usvid {
namespace {

constexpr double kGridPad = 10.0;
constexpr double kGridTitleFont = 16.0;
constexpr double kPanelTitleFont = 13.0;
constexpr double kMinArea = 20.0;
constexpr int kLayoutPasses = 3;

bool SameLegend(const std::vector<svg::LegendEntry>& a, const std::vector<svg::LegendEntry>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const auto& x, const auto& y) {
    return x.name == y.name && x.color == y.color && x.style.line == y.style.line &&
           x.style.markers == y.style.markers && x.style.dash == y.style.dash &&
           x.style.line_width == y.style.line_width &&
           x.style.marker_radius == y.style.marker_radius;
  });
}

}  // namespace

FigureGrid& FigureGrid::SetTitle(std::string title) {
  title_ = std::move(title);
  return *this;
}

FigureGrid& FigureGrid::SetXLabel(std::string label, std::string unit) {
  x_label_ = svg::WithUnit(label, unit);
  return *this;
}

FigureGrid& FigureGrid::Add(LinePlot plot, double relative_height) {
  if (!std::isfinite(relative_height) || relative_height <= 0.0) {
    throw InputError("FigureGrid::Add: relative_height = " + std::to_string(relative_height) +
                     " must be positive and finite");
  }
  panels_.push_back({std::move(plot), relative_height});
  return *this;
}

namespace {

// The request every panel starts from: one x range for all, the first fixed range, else the
// union of the extents.
LayoutRequest SharedXRange(const std::vector<LinePlot>& plots) {
  LayoutRequest shared;
  shared.allow_legend_below = false;
  shared.title_font_size = kPanelTitleFont;
  for (const LinePlot& plot : plots) {
    const auto e = plot.XExtent();
    if (!e) continue;
    if (plot.HasFixedXRange()) {
      shared.x_extent = e;
      shared.x_fixed = true;
      break;
    }
    shared.x_extent = shared.x_extent ? std::pair{std::min(shared.x_extent->first, e->first),
                                                  std::max(shared.x_extent->second, e->second)}
                                      : *e;
  }
  return shared;
}

// Heights: fixed chrome (titles, ticks, labels) per panel, the rest of `available` shared by the
// plot areas in proportion to `shares`; margins: the widest of all, so that the plot areas line
// up. Both settle in a few passes; `requests` end with the common margins, `heights` with each
// panel's height.
std::vector<LinePlotLayout> SettleLayouts(const std::vector<LinePlot>& plots,
                                          const std::vector<double>& shares, int width,
                                          double available, std::vector<LayoutRequest>& requests,
                                          std::vector<double>& heights) {
  const int n = static_cast<int>(plots.size());
  const double total_share = std::accumulate(shares.begin(), shares.end(), 0.0);
  heights.assign(n, 0.0);
  for (int i = 0; i < n; ++i) heights[i] = available * shares[i] / total_share;
  std::vector<LinePlotLayout> layouts(n);
  for (int pass = 0; pass <= kLayoutPasses; ++pass) {
    double left = 0.0;
    double right = 0.0;
    double chrome = 0.0;
    for (int i = 0; i < n; ++i) {
      layouts[i] = plots[i].Layout(width, heights[i], requests[i]);
      left = std::max(left, layouts[i].area_left);
      right = std::max(right, width - layouts[i].area_left - layouts[i].area_width);
      chrome += heights[i] - layouts[i].area_height;
    }
    if (pass == kLayoutPasses) break;
    const double areas = std::max(kMinArea * n, available - chrome);
    for (int i = 0; i < n; ++i) {
      heights[i] = heights[i] - layouts[i].area_height + areas * shares[i] / total_share;
      requests[i].min_left = left;
      requests[i].min_right = right;
    }
  }
  return layouts;
}

}  // namespace

std::string FigureGrid::ToSvg(int width, int height) const {
  if (panels_.empty()) throw InputError("FigureGrid::ToSvg: the grid has no panels");
  const int n = static_cast<int>(panels_.size());
  if (width < kMinWidth || height < kMinPanelHeight * n) {
    throw InputError("FigureGrid::ToSvg: canvas " + std::to_string(width) + " x " +
                     std::to_string(height) + " px is smaller than the minimum " +
                     std::to_string(kMinWidth) + " x " + std::to_string(kMinPanelHeight * n) +
                     " px for " + std::to_string(n) + " panels");
  }

  std::vector<LinePlot> plots;
  std::vector<double> shares;
  for (const Panel& p : panels_) {
    plots.push_back(p.plot);
    shares.push_back(p.share);
  }
  std::vector<LayoutRequest> requests(n, SharedXRange(plots));
  requests.back().x_tick_labels = true;
  for (int i = 0; i + 1 < n; ++i) {
    requests[i].x_tick_labels = false;
    requests[i].x_label = false;
  }
  // A legend that repeats the one above it is left out.
  for (int i = 1; i < n; ++i) {
    requests[i].legend = !SameLegend(plots[i].LegendEntries(), plots[i - 1].LegendEntries());
  }
  if (!x_label_.empty()) plots.back().SetXLabel(x_label_);

  const double top = title_.empty() ? 0.0 : kGridPad + kGridTitleFont;
  std::vector<double> heights;
  const std::vector<LinePlotLayout> layouts =
      SettleLayouts(plots, shares, width, height - top, requests, heights);

  std::string out = svg::DocumentStart(width, height);
  if (!title_.empty()) {
    const svg::FittedText t = svg::FitText(title_, kGridTitleFont, width - 2.0 * kGridPad, true);
    svg::AppendText(out, width / 2.0, kGridPad + kGridTitleFont * 0.8, t.text, t.font_size,
                    svg::Anchor::kMiddle, "font-weight=\"bold\"");
  }
  double y = top;
  for (int i = 0; i < n; ++i) {
    out += "<g class=\"panel\" transform=\"translate(0 " + svg::Num(y) + ")\">\n";
    plots[i].Render(out, layouts[i], requests[i],
                    std::string(svg::kIdPlaceholder) + "-" + std::to_string(i));
    out += "</g>\n";
    y += heights[i];
  }
  out += svg::kDocumentEnd;
  svg::ResolveIds(out);
  return out;
}

void FigureGrid::WriteSvg(const std::string& path, int width, int height) const {
  WriteFileAtomically(path, ToSvg(width, height));
}

}  // namespace usvid
