// LinePlot: named series y(x) drawn as a self-contained SVG for the HTML report.
//
// Axes get "nice" limits and ticks (steps of 1, 2 or 5 times a power of ten), light grid lines
// and labels "name [unit]". The legend sits outside the plot area (right of it, or below when
// the names are long), so it never covers data. Series take the colour-blind-friendly
// Okabe-Ito palette in order unless a colour is given. A non-finite x or y (NaN = not sampled)
// breaks the line. Long series are reduced per pixel column to first/min/max/last, so a 100k
// sample log draws a few thousand points and spikes stay visible. Shaded x bands (regimes such
// as "displacement / semi-displacement / planing") and vertical reference lines are labelled in
// a strip above the plot area. All text is XML-escaped.
//
// Throws usvid::InputError, naming the argument at fault, for mismatched x/y lengths, an empty
// series name, a non-finite or empty fixed range or band, a non-finite reference line, and a
// canvas smaller than kMinWidth x kMinHeight px.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "plot/axis_ticks.h"
#include "plot/legend.h"
#include "plot/series_style.h"

namespace usvid {

enum class LegendPlacement { kAuto, kRight, kBelow };

// `style` in the palette's colour number `index`; from the palette's second round on, the dash
// of every other round is changed (dotted, or solid when it was dotted), so that no two series
// look alike. Series without a colour get this; a figure that gives each method one colour in
// every panel calls it itself.
SeriesStyle PaletteStyle(SeriesStyle style, std::size_t index);

// A laid-out LinePlot: the plot area and axes inside a panel of the canvas (all in px).
struct LinePlotLayout {
  double width = 0.0;  // the whole panel
  double height = 0.0;
  double area_left = 0.0;  // the plot area
  double area_top = 0.0;
  double area_width = 0.0;
  double area_height = 0.0;
  svg::AxisTicks x;
  svg::AxisTicks y;
  bool legend_right = true;
  int annotation_rows = 0;  // rows of band / reference-line labels above the plot area
};

// What a container (FigureGrid) asks of a LinePlot's layout; ToSvg uses the defaults.
struct LayoutRequest {
  std::optional<std::pair<double, double>> x_extent;  // replaces the plot's own x extent
  bool x_fixed = false;  // x_extent is the axis limits as given (else rounded out to ticks)
  bool x_tick_labels = true;
  bool x_label = true;
  bool legend = true;  // false leaves the legend out (its room on the right stays)
  bool allow_legend_below = true;
  double min_left = 0.0;  // margins at least this wide, to align stacked plot areas
  double min_right = 0.0;
  double title_font_size = 15.0;
};

class LinePlot {
 public:
  static constexpr int kMinWidth = 240;
  static constexpr int kMinHeight = 160;

  LinePlot& SetTitle(std::string title);
  LinePlot& SetXLabel(std::string label, std::string unit = "");
  LinePlot& SetYLabel(std::string label, std::string unit = "");

  LinePlot& AddSeries(std::string name, std::span<const double> x, std::span<const double> y,
                      SeriesStyle style = {});
  LinePlot& AddSeries(std::string name, const Eigen::Ref<const Eigen::VectorXd>& x,
                      const Eigen::Ref<const Eigen::VectorXd>& y, SeriesStyle style = {});

  // Fixed axis limits instead of nice ones around the data (lo < hi, both finite).
  LinePlot& SetXRange(double lo, double hi);
  LinePlot& SetYRange(double lo, double hi);
  // A shaded band over x in [lo, hi] (either may be infinite: to the edge of the plot).
  LinePlot& AddBand(double lo, double hi, std::string label, std::string color = "");
  // A dashed vertical line at x.
  LinePlot& AddVerticalLine(double x, std::string label, std::string color = "");
  LinePlot& SetLegendPlacement(LegendPlacement placement);

  // The whole plot as an SVG document of width x height px.
  std::string ToSvg(int width, int height) const;
  // ToSvg written through WriteFileAtomically (which throws InputError on I/O failure).
  void WriteSvg(const std::string& path, int width, int height) const;

  // Composition: the finite x extent of the data, bands and lines (or the fixed range).
  std::optional<std::pair<double, double>> XExtent() const;
  bool HasFixedXRange() const { return x_range_.has_value(); }
  // The legend's entries: series names, styles and resolved colours.
  std::vector<svg::LegendEntry> LegendEntries() const;
  LinePlotLayout Layout(double width, double height, const LayoutRequest& request) const;
  // Appends the plot's SVG elements for `layout` at the origin; element ids start with `id`
  // (see svg::ResolveIds).
  void Render(std::string& out, const LinePlotLayout& layout, const LayoutRequest& request,
              const std::string& id) const;

 private:
  struct Series {
    std::string name;
    std::vector<double> x;
    std::vector<double> y;
    SeriesStyle style;
  };
  struct Band {
    double lo;
    double hi;
    std::string label;
    std::string color;
  };
  struct VerticalLine {
    double x;
    std::string label;
    std::string color;
  };
  struct AnnotationLabel {  // a band or line label placed in the strip above the plot
    double centre;
    std::string text;
    int row;
  };

  std::optional<std::pair<double, double>> YExtent(double x_lo, double x_hi) const;
  bool HasData() const;  // any point with finite x and y
  std::vector<AnnotationLabel> PlaceAnnotations(const svg::AxisTicks& x, double area_left,
                                                double area_width) const;
  std::size_t PaletteIndex(std::size_t series) const;  // among the series that take the palette
  std::string ColorOf(std::size_t series) const;
  // The series' style with its colour resolved (PaletteStyle when it has none).
  SeriesStyle StyleOf(std::size_t series) const;
  void RenderBands(std::string& out, const LinePlotLayout& layout) const;
  void RenderGrid(std::string& out, const LinePlotLayout& layout) const;
  // Lines (and lone samples between gaps) when `markers` is false, else the markers.
  void RenderSeries(std::string& out, const LinePlotLayout& layout, bool markers) const;
  void RenderTexts(std::string& out, const LinePlotLayout& layout,
                   const LayoutRequest& request) const;

  std::string title_;
  std::string x_label_;
  std::string y_label_;
  std::vector<Series> series_;
  std::vector<Band> bands_;
  std::vector<VerticalLine> lines_;
  std::optional<std::pair<double, double>> x_range_;
  std::optional<std::pair<double, double>> y_range_;
  LegendPlacement legend_ = LegendPlacement::kAuto;
};

}  // namespace usvid
