#include "plot/legend.h"

#include <algorithm>
#include <vector>

#include "plot/svg_text.h"

namespace usvid::svg {
namespace {

constexpr double kSwatchLength = 26.0;
constexpr double kSwatchGap = 6.0;
constexpr double kEntrySpacing = 18.0;  // between entries of one row

double EntryWidth(const LegendEntry& e) {
  return kSwatchLength + kSwatchGap + TextWidth(e.name, kLegendFontSize);
}

// Entries per row when wrapped to `width`: each row holds at least one entry.
std::vector<std::vector<const LegendEntry*>> WrapRows(std::span<const LegendEntry> entries,
                                                      double width) {
  std::vector<std::vector<const LegendEntry*>> rows;
  double used = 0.0;
  for (const LegendEntry& e : entries) {
    const double w = EntryWidth(e);
    if (rows.empty() || (used + kEntrySpacing + w > width && !rows.back().empty())) {
      rows.emplace_back();
      used = -kEntrySpacing;
    }
    rows.back().push_back(&e);
    used += kEntrySpacing + w;
  }
  return rows;
}

void DrawEntry(std::string& out, const LegendEntry& e, double x, double row_top) {
  const double mid = row_top + kLegendRowHeight / 2.0;
  DrawSwatch(out, e.style, e.color, x, mid, kSwatchLength);
  AppendText(out, x + kSwatchLength + kSwatchGap, mid + kLegendFontSize * 0.35, e.name,
             kLegendFontSize, Anchor::kStart);
}

}  // namespace

double LegendColumnWidth(std::span<const LegendEntry> entries) {
  double widest = 0.0;
  for (const LegendEntry& e : entries) widest = std::max(widest, EntryWidth(e));
  return widest;
}

void DrawLegendColumn(std::string& out, std::span<const LegendEntry> entries, double x,
                      double top) {
  out += "<g class=\"legend\">\n";
  for (std::size_t i = 0; i < entries.size(); ++i) {
    DrawEntry(out, entries[i], x, top + static_cast<double>(i) * kLegendRowHeight);
  }
  out += "</g>\n";
}

double LegendRowsHeight(std::span<const LegendEntry> entries, double width) {
  return static_cast<double>(WrapRows(entries, width).size()) * kLegendRowHeight;
}

void DrawLegendRows(std::string& out, std::span<const LegendEntry> entries, double x, double top,
                    double width) {
  out += "<g class=\"legend\">\n";
  double row_top = top;
  for (const auto& row : WrapRows(entries, width)) {
    double row_width = -kEntrySpacing;
    for (const LegendEntry* e : row) row_width += kEntrySpacing + EntryWidth(*e);
    double left = x + std::max(0.0, (width - row_width) / 2.0);
    for (const LegendEntry* e : row) {
      DrawEntry(out, *e, left, row_top);
      left += EntryWidth(*e) + kEntrySpacing;
    }
    row_top += kLegendRowHeight;
  }
  out += "</g>\n";
}

void DrawSwatch(std::string& out, const SeriesStyle& style, const std::string& color, double x,
                double y, double length) {
  const std::string stroke = Escape(color);
  if (style.line) {
    out += "<line x1=\"" + Num(x) + "\" y1=\"" + Num(y) + "\" x2=\"" + Num(x + length) +
           "\" y2=\"" + Num(y) + "\" stroke=\"" + stroke + "\" stroke-width=\"" +
           Num(style.line_width) + "\"";
    out += DashAttribute(style.dash);
    out += "/>\n";
  }
  if (style.markers) {
    out += "<circle cx=\"" + Num(x + length / 2.0) + "\" cy=\"" + Num(y) + "\" r=\"" +
           Num(std::max(style.marker_radius, 2.5)) + "\" fill=\"" + stroke + "\"/>\n";
  }
}

}  // namespace usvid::svg
