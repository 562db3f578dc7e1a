// The measures of a HeatMap's layout, shared by its layout (heat_map.cc) and its renderer
// (heat_map_render.cc). Internal to the plot library.
#pragma once

#include <string_view>

#include "plot/axis_ticks.h"
#include "plot/heat_map.h"

namespace usvid {
namespace heat_map_metrics {

inline constexpr double kPad = 10.0;
inline constexpr double kTitleFont = 15.0;
inline constexpr double kLabelFont = 12.0;     // row and column labels
inline constexpr double kAxisFont = 12.5;      // what rows and columns are
inline constexpr double kTickFont = 11.0;      // colour-bar ticks
inline constexpr double kMaxValueFont = 13.0;  // cell text
inline constexpr double kMinValueFont = 7.0;   // below this the cell text is left out
inline constexpr double kBarWidth = 14.0;
inline constexpr double kBarGap = 18.0;  // cells to colour bar
inline constexpr double kCellGap = 2.0;  // white gap between cells
inline constexpr double kCos45 = 0.70710678118654752;
inline constexpr std::string_view kMuted = "fill=\"#555\"";

}  // namespace heat_map_metrics

// Where the parts of a HeatMap go on a width x height px canvas.
struct HeatMap::Geometry {
  double width = 0.0;
  double height = 0.0;
  double cells_left = 0.0;
  double cells_top = 0.0;
  double cell_width = 0.0;
  double cell_height = 0.0;
  bool rotate_columns = false;
  double value_font = 0.0;
  double lo = 0.0;  // colour-scale limits
  double hi = 1.0;
  svg::AxisTicks ticks;
  int rows = 0;
  int columns = 0;

  double CellsRight() const { return cells_left + cell_width * columns; }
  double CellsBottom() const { return cells_top + cell_height * rows; }
};

}  // namespace usvid
