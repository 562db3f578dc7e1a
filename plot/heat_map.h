// HeatMap: a table of values as coloured cells, e.g. the fit [%] of each identification method
// (rows) on each test maneuver (columns), drawn as a self-contained SVG.
//
// Each cell prints its value (dark or light text, whichever contrasts with the fill); a NaN
// cell is hatched grey and reads "n/a". Fills follow viridis (dark purple = low, yellow = high)
// over the value range (the finite min..max, or SetValueRange; values outside take the end
// colour), explained by a colour bar with nice ticks to the right. Column labels sit above the
// cells and turn by 45 degrees when they do not fit the cell width. All text is XML-escaped.
//
// Throws usvid::InputError, naming the argument at fault, for: no rows or columns, label
// counts that do not match the value matrix, an empty or non-finite value range, decimals
// outside 0..9, and a canvas smaller than kMinWidth x kMinHeight px.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace usvid {

class HeatMap {
 public:
  static constexpr int kMinWidth = 200;
  static constexpr int kMinHeight = 120;

  // values(r, c) belongs to row_labels[r] and column_labels[c]; NaN = not available.
  HeatMap(std::vector<std::string> row_labels, std::vector<std::string> column_labels,
          Eigen::MatrixXd values);

  HeatMap& SetTitle(std::string title);
  // Names of what the rows and the columns are, e.g. "method" and "test maneuver".
  HeatMap& SetAxisLabels(std::string rows, std::string columns);
  // The colour bar's label, e.g. ("fit", "%") -> "fit [%]".
  HeatMap& SetValueLabel(std::string label, std::string unit = "");
  // Colour-scale limits (lo < hi, finite) instead of the data's min..max.
  HeatMap& SetValueRange(double lo, double hi);
  // Cell text: the value with `decimals` decimals followed by `suffix` (default: 1, "").
  HeatMap& SetDecimals(int decimals, std::string suffix = "");
  // Cell text from a function instead (called for finite values only).
  HeatMap& SetFormatter(std::function<std::string(double)> format);

  // The text printed in a cell holding `value`: "n/a" for NaN.
  std::string FormatValue(double value) const;
  // The colour-scale limits used when drawing.
  std::pair<double, double> ValueRange() const;

  std::string ToSvg(int width, int height) const;
  // ToSvg written through WriteFileAtomically (which throws InputError on I/O failure).
  void WriteSvg(const std::string& path, int width, int height) const;

 private:
  struct Geometry;
  Geometry Measure(double width, double height) const;
  void RenderCells(std::string& out, const Geometry& g, const std::string& id) const;
  void RenderLabels(std::string& out, const Geometry& g) const;
  void RenderColorBar(std::string& out, const Geometry& g, const std::string& id) const;

  std::vector<std::string> row_labels_;
  std::vector<std::string> column_labels_;
  Eigen::MatrixXd values_;
  std::string title_;
  std::string row_axis_;
  std::string column_axis_;
  std::string value_label_;
  std::optional<std::pair<double, double>> range_;
  int decimals_ = 1;
  std::string suffix_;
  std::function<std::string(double)> format_;
};

}  // namespace usvid
