// FigureGrid: LinePlots stacked vertically in one SVG with a shared x axis, e.g. the u, v and r
// channels of one run. All panels get one x range (the union of their x extents, or the first
// panel's fixed x range), their plot areas are aligned left and right, and only the bottom
// panel carries x tick labels and the x-axis label (the grid's, when set). Each panel keeps its
// title (smaller), y axis, bands, reference lines and legend (to the right of its plot area).
// Plot-area heights are proportional to the panels' relative heights.
//
// Throws usvid::InputError for a relative height that is not positive and finite, rendering an
// empty grid, and a canvas smaller than kMinWidth x (kMinPanelHeight per panel) px.
#pragma once

#include <string>
#include <vector>

#include "plot/svg_plot.h"

namespace usvid {

class FigureGrid {
 public:
  static constexpr int kMinWidth = LinePlot::kMinWidth;
  static constexpr int kMinPanelHeight = 60;

  FigureGrid& SetTitle(std::string title);
  // The x-axis label under the bottom panel, replacing that panel's own.
  FigureGrid& SetXLabel(std::string label, std::string unit = "");
  // Appends a panel below the others (the plot is copied).
  FigureGrid& Add(LinePlot plot, double relative_height = 1.0);

  std::string ToSvg(int width, int height) const;
  // ToSvg written through WriteFileAtomically (which throws InputError on I/O failure).
  void WriteSvg(const std::string& path, int width, int height) const;

 private:
  struct Panel {
    LinePlot plot;
    double share;
  };

  std::string title_;
  std::string x_label_;
  std::vector<Panel> panels_;
};

}  // namespace usvid
