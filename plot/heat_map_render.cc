// HeatMap drawing: cells with their printed values (hatched "n/a" for NaN), row and column
// labels, and the colour bar. Coordinates are those of a HeatMap::Geometry.
#include <algorithm>
#include <cmath>

#include "plot/colors.h"
#include "plot/heat_map.h"
#include "plot/heat_map_geometry.h"
#include "plot/svg_text.h"

namespace usvid {
namespace {

using namespace heat_map_metrics;  // NOLINT(build/namespaces): the shared layout measures
using svg::Num;

constexpr int kGradientStops = 11;

std::string Rect(double x, double y, double w, double h, std::string_view fill) {
  return "<rect x=\"" + Num(x) + "\" y=\"" + Num(y) + "\" width=\"" + Num(w) + "\" height=\"" +
         Num(h) + "\" fill=\"" + std::string(fill) + "\"";
}

}  // namespace

void HeatMap::RenderCells(std::string& out, const Geometry& g, const std::string& id) const {
  out += "<defs><pattern id=\"" + id +
         "-na\" width=\"6\" height=\"6\" patternUnits=\"userSpaceOnUse\" "
         "patternTransform=\"rotate(45)\"><rect width=\"6\" height=\"6\" fill=\"#f3f3f3\"/>"
         "<line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"6\" stroke=\"#d0d0d0\" stroke-width=\"2\"/>"
         "</pattern></defs>\n";
  const double w = g.cell_width - kCellGap;
  const double h = g.cell_height - kCellGap;
  for (int r = 0; r < g.rows; ++r) {
    for (int c = 0; c < g.columns; ++c) {
      const double v = values_(r, c);
      const double x = g.cells_left + c * g.cell_width + kCellGap / 2.0;
      const double y = g.cells_top + r * g.cell_height + kCellGap / 2.0;
      const std::string text = FormatValue(v);
      out += "<g class=\"cell\">";
      out += "<title>" + svg::Escape(row_labels_[r] + " / " + column_labels_[c] + ": " + text) +
             "</title>";
      std::string text_fill;
      if (std::isnan(v)) {
        out += Rect(x, y, w, h, "url(#" + id + "-na)") + "/>";
        text_fill = "fill=\"#666\"";
      } else {
        const svg::Rgb fill = svg::Viridis((v - g.lo) / (g.hi - g.lo));
        out += Rect(x, y, w, h, svg::Hex(fill)) + "/>";
        text_fill = svg::RelativeLuminance(fill) > 0.35 ? "fill=\"#1a1a1a\"" : "fill=\"#fff\"";
      }
      out += '\n';
      if (g.value_font >= kMinValueFont) {
        svg::AppendText(out, x + w / 2.0, y + h / 2.0 + g.value_font * 0.35, text, g.value_font,
                        svg::Anchor::kMiddle, text_fill);
      }
      out += "</g>\n";
    }
  }
}

void HeatMap::RenderLabels(std::string& out, const Geometry& g) const {
  const double cells_centre_x = (g.cells_left + g.CellsRight()) / 2.0;
  double y = kPad;
  if (!title_.empty()) {
    const svg::FittedText t = svg::FitText(title_, kTitleFont, g.width - 2.0 * kPad, true);
    const double half = svg::TextWidth(t.text, t.font_size, true) / 2.0;
    const double x =
        std::clamp(cells_centre_x, kPad + half, std::max(kPad + half, g.width - kPad - half));
    svg::AppendText(out, x, y + kTitleFont * 0.8, t.text, t.font_size, svg::Anchor::kMiddle,
                    "font-weight=\"bold\"");
    y += kTitleFont + 10.0;
  }
  if (!column_axis_.empty()) {
    svg::AppendText(out, cells_centre_x, y + kAxisFont * 0.8, column_axis_, kAxisFont,
                    svg::Anchor::kMiddle, std::string(kMuted) + " " + std::string(svg::kAxisLabelClass));
  }
  if (!row_axis_.empty()) {
    double widest = 0.0;
    for (const std::string& label : row_labels_) {
      widest = std::max(widest, svg::TextWidth(label, kLabelFont));
    }
    svg::AppendVerticalText(out, g.cells_left - 8.0 - widest - 10.0 - kAxisFont * 0.2,
                            (g.cells_top + g.CellsBottom()) / 2.0, row_axis_, kAxisFont,
                            std::string(kMuted) + " " + std::string(svg::kAxisLabelClass));
  }
  out += "<g class=\"row-labels\">\n";
  for (int r = 0; r < g.rows; ++r) {
    svg::AppendText(out, g.cells_left - 8.0,
                    g.cells_top + (r + 0.5) * g.cell_height + kLabelFont * 0.35, row_labels_[r],
                    kLabelFont, svg::Anchor::kEnd);
  }
  out += "</g>\n<g class=\"column-labels\">\n";
  for (int c = 0; c < g.columns; ++c) {
    const double x = g.cells_left + (c + 0.5) * g.cell_width;
    if (g.rotate_columns) {
      const double base = g.cells_top - 6.0;
      svg::AppendText(out, x, base, column_labels_[c], kLabelFont, svg::Anchor::kStart,
                      "transform=\"rotate(-45 " + Num(x) + " " + Num(base) + ")\"");
    } else {
      svg::AppendText(out, x, g.cells_top - 8.0, column_labels_[c], kLabelFont,
                      svg::Anchor::kMiddle);
    }
  }
  out += "</g>\n";
}

void HeatMap::RenderColorBar(std::string& out, const Geometry& g, const std::string& id) const {
  const double left = g.CellsRight() + kBarGap;
  const double top = g.cells_top + kCellGap / 2.0;
  const double height = g.CellsBottom() - g.cells_top - kCellGap;
  out += "<defs><linearGradient id=\"" + id + "-scale\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">";
  for (int i = 0; i < kGradientStops; ++i) {
    const double t = static_cast<double>(i) / (kGradientStops - 1);
    out += "<stop offset=\"" + Num(t) + "\" stop-color=\"" + svg::Hex(svg::Viridis(t)) + "\"/>";
  }
  out += "</linearGradient></defs>\n<g class=\"color-bar\">\n";
  out += Rect(left, top, kBarWidth, height, "url(#" + id + "-scale)") + "/>\n";
  double widest = 0.0;
  for (std::size_t i = 0; i < g.ticks.values.size(); ++i) {
    const double y = top + height * (g.hi - g.ticks.values[i]) / (g.hi - g.lo);
    out += "<line x1=\"" + Num(left + kBarWidth) + "\" y1=\"" + Num(y) + "\" x2=\"" +
           Num(left + kBarWidth + 4.0) + "\" y2=\"" + Num(y) + "\" stroke=\"#555\"/>\n";
    svg::AppendText(out, left + kBarWidth + 6.0, y + kTickFont * 0.35, g.ticks.labels[i], kTickFont,
                    svg::Anchor::kStart, kMuted);
    widest = std::max(widest, svg::TextWidth(g.ticks.labels[i], kTickFont));
  }
  if (!value_label_.empty()) {
    svg::AppendVerticalText(out, left + kBarWidth + 6.0 + widest + 8.0 + kAxisFont * 0.8,
                            top + height / 2.0, value_label_, kAxisFont);
  }
  out += "</g>\n";
}

}  // namespace usvid
