// LinePlot drawing: bands, grid and frame, reference lines, the series (clipped to the plot
// area), then the text around it. Coordinates are those of a LinePlotLayout.
#include <algorithm>
#include <cmath>

#include "plot/colors.h"
#include "plot/decimate.h"
#include "plot/legend.h"
#include "plot/line_plot_metrics.h"
#include "plot/svg_plot.h"
#include "plot/svg_text.h"

namespace usvid {
namespace {

using namespace line_plot_metrics;  // NOLINT(build/namespaces): the shared layout measures
using svg::Num;

constexpr std::string_view kBandColors[] = {"#f2f4f7", "#e4e8ee"};
constexpr std::string_view kGridColor = "#e0e0e0";
constexpr std::string_view kZeroColor = "#bdbdbd";
constexpr std::string_view kFrameColor = "#8c8c8c";
constexpr std::string_view kLineColor = "#444444";
constexpr std::string_view kMutedText = "fill=\"#555\"";

svg::AxisMap XMap(const LinePlotLayout& L) {
  const double scale = L.area_width / (L.x.hi - L.x.lo);
  return {L.area_left - L.x.lo * scale, scale};
}

svg::AxisMap YMap(const LinePlotLayout& L) {
  const double scale = -L.area_height / (L.y.hi - L.y.lo);
  return {L.area_top + L.area_height - L.y.lo * scale, scale};
}

void Line(std::string& out, double x1, double y1, double x2, double y2, std::string_view color,
          std::string_view extra = "") {
  out += "<line x1=\"" + Num(x1) + "\" y1=\"" + Num(y1) + "\" x2=\"" + Num(x2) + "\" y2=\"" +
         Num(y2) + "\" stroke=\"" + std::string(color) + "\"" + std::string(extra) + "/>\n";
}

std::string ClipPath(const std::string& id, const LinePlotLayout& L, double margin) {
  return "<clipPath id=\"" + id + "\"><rect x=\"" + Num(L.area_left - margin) + "\" y=\"" +
         Num(L.area_top - margin) + "\" width=\"" + Num(L.area_width + 2.0 * margin) +
         "\" height=\"" + Num(L.area_height + 2.0 * margin) + "\"/></clipPath>";
}

// Grid lines are drawn on the pixel grid (x.5) so that they stay one crisp pixel wide.
double Crisp(double px) { return std::floor(px) + 0.5; }

}  // namespace

void LinePlot::Render(std::string& out, const LinePlotLayout& layout, const LayoutRequest& request,
                      const std::string& id) const {
  const LinePlotLayout& L = layout;
  // Lines are clipped to the plot area; markers on its edge are drawn whole.
  double radius = 0.0;
  for (const Series& s : series_) {
    if (s.style.markers) radius = std::max(radius, s.style.marker_radius);
  }
  out += "<defs>" + ClipPath(id + "-area", L, 0.0) + ClipPath(id + "-markers", L, radius + 1.0) +
         "</defs>\n";
  out += "<g clip-path=\"url(#" + id + "-area)\">\n";
  RenderBands(out, L);
  RenderGrid(out, L);
  RenderSeries(out, L, false);
  out += "</g>\n<g clip-path=\"url(#" + id + "-markers)\">\n";
  RenderSeries(out, L, true);
  out += "</g>\n";
  out += "<rect class=\"frame\" x=\"" + Num(Crisp(L.area_left)) + "\" y=\"" +
         Num(Crisp(L.area_top)) + "\" width=\"" + Num(std::round(L.area_width)) + "\" height=\"" +
         Num(std::round(L.area_height)) + "\" fill=\"none\" stroke=\"" + std::string(kFrameColor) +
         "\"/>\n";
  RenderTexts(out, L, request);
}

void LinePlot::RenderBands(std::string& out, const LinePlotLayout& L) const {
  const svg::AxisMap px = XMap(L);
  for (std::size_t i = 0; i < bands_.size(); ++i) {
    const Band& b = bands_[i];
    const double lo = std::max(b.lo, L.x.lo);
    const double hi = std::min(b.hi, L.x.hi);
    if (!(lo < hi)) continue;
    const std::string color =
        b.color.empty() ? std::string(kBandColors[i % 2]) : svg::Escape(b.color);
    out += "<rect class=\"band\" x=\"" + Num(px(lo)) + "\" y=\"" + Num(L.area_top) + "\" width=\"" +
           Num(px(hi) - px(lo)) + "\" height=\"" + Num(L.area_height) + "\" fill=\"" + color +
           "\"/>\n";
  }
}

void LinePlot::RenderGrid(std::string& out, const LinePlotLayout& L) const {
  const svg::AxisMap px = XMap(L);
  const svg::AxisMap py = YMap(L);
  const double bottom = L.area_top + L.area_height;
  const double right = L.area_left + L.area_width;
  out += "<g class=\"grid\" stroke-width=\"1\">\n";
  for (const double v : L.x.values) {
    Line(out, Crisp(px(v)), L.area_top, Crisp(px(v)), bottom, kGridColor);
  }
  for (const double v : L.y.values) {
    const bool zero = std::abs(v) < 1e-9 * L.y.step && L.y.lo < v && v < L.y.hi;
    Line(out, L.area_left, Crisp(py(v)), right, Crisp(py(v)), zero ? kZeroColor : kGridColor);
  }
  out += "</g>\n";
  for (const VerticalLine& l : lines_) {
    const std::string color = l.color.empty() ? std::string(kLineColor) : svg::Escape(l.color);
    Line(out, px(l.x), L.area_top, px(l.x), bottom, color,
         " class=\"reference\" stroke-width=\"1.2\" stroke-dasharray=\"5 3\"");
  }
}

void LinePlot::RenderSeries(std::string& out, const LinePlotLayout& L, bool markers) const {
  const svg::AxisMap px = XMap(L);
  const svg::AxisMap py = YMap(L);
  for (std::size_t i = 0; i < series_.size(); ++i) {
    const Series& s = series_[i];
    if (markers ? !s.style.markers : !s.style.line) continue;
    const std::string color = svg::Escape(ColorOf(i));
    out += "<g class=\"series\" data-name=\"" + svg::Escape(s.name) + "\">\n";
    const std::vector<svg::Polyline> lines = svg::ToPolylines(s.x, s.y, px, py);
    if (markers) {
      out += "<g class=\"markers\" fill=\"" + color + "\">\n";
      for (const svg::Polyline& line : lines) {
        for (const svg::PixelPoint& p : line) {
          out += "<circle cx=\"" + Num(p.x) + "\" cy=\"" + Num(p.y) + "\" r=\"" +
                 Num(s.style.marker_radius) + "\"/>\n";
        }
      }
      out += "</g>\n</g>\n";
      continue;
    }
    std::string d;
    std::string dots;  // a sample between two gaps has no line: drawn as a dot
    for (const svg::Polyline& line : lines) {
      if (line.size() == 1) {
        dots += "<circle cx=\"" + Num(line[0].x) + "\" cy=\"" + Num(line[0].y) + "\" r=\"" +
                Num(s.style.line_width) + "\"/>\n";
        continue;
      }
      for (std::size_t k = 0; k < line.size(); ++k) {
        d += (k == 0 ? (d.empty() ? "M" : " M") : " L") + Num(line[k].x) + "," + Num(line[k].y);
      }
    }
    if (!d.empty()) {
      out += "<path d=\"" + d + "\" fill=\"none\" stroke=\"" + color + "\" stroke-width=\"" +
             Num(s.style.line_width) + "\" stroke-linejoin=\"round\"";
      out += DashAttribute(StyleOf(i).dash);
      out += "/>\n";
    }
    if (!dots.empty() && !s.style.markers) out += "<g fill=\"" + color + "\">\n" + dots + "</g>\n";
    out += "</g>\n";
  }
}

void LinePlot::RenderTexts(std::string& out, const LinePlotLayout& L,
                           const LayoutRequest& request) const {
  const svg::AxisMap px = XMap(L);
  const svg::AxisMap py = YMap(L);
  const double bottom = L.area_top + L.area_height;
  const double centre = L.area_left + L.area_width / 2.0;
  out += "<g class=\"ticks\" " + std::string(kMutedText) + ">\n";
  for (std::size_t i = 0; i < L.y.values.size(); ++i) {
    svg::AppendText(out, L.area_left - kTickGap, py(L.y.values[i]) + kTickFont * 0.35,
                    L.y.labels[i], kTickFont, svg::Anchor::kEnd);
  }
  if (request.x_tick_labels) {
    for (std::size_t i = 0; i < L.x.values.size(); ++i) {
      svg::AppendText(out, px(L.x.values[i]), bottom + kTickGap + kTickFont * 0.8, L.x.labels[i],
                      kTickFont, svg::Anchor::kMiddle);
    }
  }
  out += "</g>\n";
  if (!title_.empty()) {
    const svg::FittedText t =
        svg::FitText(title_, request.title_font_size, L.width - 2.0 * kPad, true);
    const double half = svg::TextWidth(t.text, t.font_size, true) / 2.0;
    const double x = std::clamp(centre, kPad + half, std::max(kPad + half, L.width - kPad - half));
    svg::AppendText(out, x, kPad + request.title_font_size * 0.8, t.text, t.font_size,
                    svg::Anchor::kMiddle, "font-weight=\"bold\"");
  }
  if (!y_label_.empty()) {
    const svg::FittedText t = svg::FitText(y_label_, kLabelFont, L.area_height + 20.0);
    svg::AppendVerticalText(out, kPad + kLabelFont * 0.8, L.area_top + L.area_height / 2.0, t.text,
                            t.font_size, svg::kAxisLabelClass);
  }
  if (!HasData()) {
    svg::AppendText(out, centre, L.area_top + L.area_height / 2.0, "no data", kLabelFont,
                    svg::Anchor::kMiddle, kMutedText);
  }
  double below = bottom + (request.x_tick_labels ? kTickGap + kTickFont : 0.0);
  if (request.x_label && !x_label_.empty()) {
    below += kLabelGap + kLabelFont;
    const svg::FittedText t = svg::FitText(x_label_, kLabelFont, L.width - 2.0 * kPad);
    svg::AppendText(out, centre, below - kLabelFont * 0.2, t.text, t.font_size,
                    svg::Anchor::kMiddle, svg::kAxisLabelClass);
  }
  for (const AnnotationLabel& a : PlaceAnnotations(L.x, L.area_left, L.area_width)) {
    svg::AppendText(out, a.centre, L.area_top - 5.0 - a.row * kAnnotationRow, a.text,
                    kAnnotationFont, svg::Anchor::kMiddle,
                    "class=\"annotation\" " + std::string(kMutedText));
  }
  const std::vector<svg::LegendEntry> legend = LegendEntries();
  if (legend.empty() || !request.legend) return;
  if (L.legend_right) {
    svg::DrawLegendColumn(out, legend, L.area_left + L.area_width + kLegendGap, L.area_top);
  } else {
    const double width = L.width - 2.0 * kPad;
    svg::DrawLegendRows(out, legend, kPad, L.height - kPad - svg::LegendRowsHeight(legend, width),
                        width);
  }
}

}  // namespace usvid
