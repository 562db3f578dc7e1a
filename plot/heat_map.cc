#include "plot/heat_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "core/atomic_file.h"
#include "core/error.h"
#include "plot/axis_ticks.h"
#include "plot/colors.h"
#include "plot/heat_map_geometry.h"
#include "plot/svg_text.h"

namespace usvid {
namespace {

using namespace heat_map_metrics;  // NOLINT(build/namespaces): the shared layout measures

double WidestOf(const std::vector<std::string>& labels, double font) {
  double w = 0.0;
  for (const std::string& s : labels) w = std::max(w, svg::TextWidth(s, font));
  return w;
}

}  // namespace

HeatMap::HeatMap(std::vector<std::string> row_labels, std::vector<std::string> column_labels,
                 Eigen::MatrixXd values)
    : row_labels_(std::move(row_labels)),
      column_labels_(std::move(column_labels)),
      values_(std::move(values)) {
  if (values_.rows() == 0 || values_.cols() == 0) {
    throw InputError("HeatMap: the value matrix is empty (" + std::to_string(values_.rows()) +
                     " x " + std::to_string(values_.cols()) + ")");
  }
  if (static_cast<Eigen::Index>(row_labels_.size()) != values_.rows() ||
      static_cast<Eigen::Index>(column_labels_.size()) != values_.cols()) {
    throw InputError("HeatMap: " + std::to_string(row_labels_.size()) + " row labels and " +
                     std::to_string(column_labels_.size()) + " column labels for a " +
                     std::to_string(values_.rows()) + " x " + std::to_string(values_.cols()) +
                     " value matrix");
  }
}

HeatMap& HeatMap::SetTitle(std::string title) {
  title_ = std::move(title);
  return *this;
}

HeatMap& HeatMap::SetAxisLabels(std::string rows, std::string columns) {
  row_axis_ = std::move(rows);
  column_axis_ = std::move(columns);
  return *this;
}

HeatMap& HeatMap::SetValueLabel(std::string label, std::string unit) {
  value_label_ = svg::WithUnit(label, unit);
  return *this;
}

HeatMap& HeatMap::SetValueRange(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi)) {
    throw InputError("HeatMap::SetValueRange: range [" + svg::Short(lo) + ", " + svg::Short(hi) +
                     "] must be finite with lo < hi");
  }
  range_ = std::pair{lo, hi};
  return *this;
}

HeatMap& HeatMap::SetDecimals(int decimals, std::string suffix) {
  if (decimals < 0 || decimals > 9) {
    throw InputError("HeatMap::SetDecimals: decimals = " + std::to_string(decimals) +
                     " is outside 0..9");
  }
  decimals_ = decimals;
  suffix_ = std::move(suffix);
  format_ = nullptr;
  return *this;
}

HeatMap& HeatMap::SetFormatter(std::function<std::string(double)> format) {
  format_ = std::move(format);
  return *this;
}

std::string HeatMap::FormatValue(double value) const {
  if (std::isnan(value)) return "n/a";
  if (format_ && std::isfinite(value)) return format_(value);
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals_, value);
  std::string s = buf;
  if (s.front() == '-') s.replace(0, 1, "\u2212");
  return s + suffix_;
}

std::pair<double, double> HeatMap::ValueRange() const {
  if (range_) return *range_;
  double lo = INFINITY;
  double hi = -INFINITY;
  for (const double v : values_.reshaped()) {
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (!(lo <= hi)) return {0.0, 1.0};
  if (lo == hi)
    return {lo - std::max(1.0, std::abs(lo) * 0.1), hi + std::max(1.0, std::abs(hi) * 0.1)};
  return {lo, hi};
}

HeatMap::Geometry HeatMap::Measure(double width, double height) const {
  Geometry g;
  g.width = width;
  g.height = height;
  g.rows = static_cast<int>(values_.rows());
  g.columns = static_cast<int>(values_.cols());
  std::tie(g.lo, g.hi) = ValueRange();

  const double top = kPad + (title_.empty() ? 0.0 : kTitleFont + 10.0) +
                     (column_axis_.empty() ? 0.0 : kAxisFont + 6.0);
  const double left =
      kPad + (row_axis_.empty() ? 0.0 : kAxisFont + 8.0) + WidestOf(row_labels_, kLabelFont) + 8.0;
  // The colour bar's tick labels need the bar's height; a first guess is refined below.
  double bar_height = std::max(40.0, height - top - kPad - 24.0);
  g.ticks = svg::FixedTicks(g.lo, g.hi, std::clamp(static_cast<int>(bar_height / 32.0) + 1, 2, 9));
  const double right = kBarGap + kBarWidth + 5.0 + svg::WidestLabel(g.ticks, kTickFont) +
                       (value_label_.empty() ? 0.0 : 8.0 + kAxisFont) + kPad;
  g.cells_left = left;
  g.cell_width = std::max(8.0, (width - left - right) / g.columns);

  const double widest_column = WidestOf(column_labels_, kLabelFont);
  g.rotate_columns = widest_column > g.cell_width - 6.0;
  double header = kLabelFont + 8.0;
  if (g.rotate_columns) {
    header = (widest_column + kLabelFont) * kCos45 + 8.0;
    // The last label leans right: keep it on the canvas.
    const double overflow = g.CellsRight() - g.cell_width / 2.0 +
                            svg::TextWidth(column_labels_.back(), kLabelFont) * kCos45 -
                            (width - kPad);
    if (overflow > 0.0) g.cell_width = std::max(8.0, g.cell_width - overflow / g.columns);
  }
  g.cells_top = top + header;
  g.cell_height = std::max(8.0, (height - g.cells_top - kPad) / g.rows);
  bar_height = g.cell_height * g.rows;
  g.ticks = svg::FixedTicks(g.lo, g.hi, std::clamp(static_cast<int>(bar_height / 32.0) + 1, 2, 9));

  double widest_value = 0.0;
  for (const double v : values_.reshaped()) {
    widest_value = std::max(widest_value, svg::TextWidth(FormatValue(v), 1.0));
  }
  g.value_font = std::min({kMaxValueFont, 0.45 * g.cell_height,
                           (g.cell_width - kCellGap - 6.0) / std::max(widest_value, 1e-9)});
  return g;
}

std::string HeatMap::ToSvg(int width, int height) const {
  if (width < kMinWidth || height < kMinHeight) {
    throw InputError("HeatMap::ToSvg: canvas " + std::to_string(width) + " x " +
                     std::to_string(height) + " px is smaller than the minimum " +
                     std::to_string(kMinWidth) + " x " + std::to_string(kMinHeight) + " px");
  }
  const std::string id(svg::kIdPlaceholder);
  const Geometry g = Measure(width, height);
  std::string out = svg::DocumentStart(width, height);
  RenderCells(out, g, id);
  RenderLabels(out, g);
  RenderColorBar(out, g, id);
  out += svg::kDocumentEnd;
  svg::ResolveIds(out);
  return out;
}

void HeatMap::WriteSvg(const std::string& path, int width, int height) const {
  WriteFileAtomically(path, ToSvg(width, height));
}

}  // namespace usvid
