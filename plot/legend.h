// The legend of a LinePlot, drawn outside the plot area so that it never covers data: either a
// column to the right of the plot (one entry per row) or rows below it (entries wrapped to the
// available width and centred). Each entry shows the series' line/marker sample and its name.
// Nothing here throws.
#pragma once

#include <span>
#include <string>

#include "plot/series_style.h"

namespace usvid::svg {

struct LegendEntry {
  std::string name;
  SeriesStyle style;
  std::string color;  // resolved colour
};

inline constexpr double kLegendFontSize = 12.0;
inline constexpr double kLegendRowHeight = 18.0;

// Width [px] of the column legend, without outer margins.
double LegendColumnWidth(std::span<const LegendEntry> entries);
// Draws the column with its first row's top at (x, top).
void DrawLegendColumn(std::string& out, std::span<const LegendEntry> entries, double x, double top);

// Height [px] of the row legend wrapped to `width`.
double LegendRowsHeight(std::span<const LegendEntry> entries, double width);
// Draws the rows centred in [x, x + width], the first row's top at `top`.
void DrawLegendRows(std::string& out, std::span<const LegendEntry> entries, double x, double top,
                    double width);

// The line/marker sample of a series, `length` px long, centred vertically at `y`.
void DrawSwatch(std::string& out, const SeriesStyle& style, const std::string& color, double x,
                double y, double length);

}  // namespace usvid::svg
