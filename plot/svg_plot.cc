#include "plot/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/atomic_file.h"
#include "core/error.h"
#include "plot/colors.h"
#include "plot/svg_text.h"

namespace usvid {
namespace {

using Range = std::pair<double, double>;

void CheckRange(const char* what, double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi)) {
    throw InputError(std::string("LinePlot::") + what + ": range [" + svg::Short(lo) + ", " +
                     svg::Short(hi) + "] must be finite with lo < hi");
  }
}

void Grow(std::optional<Range>& r, double v) {
  if (!std::isfinite(v)) return;
  if (!r) r = Range{v, v};
  r->first = std::min(r->first, v);
  r->second = std::max(r->second, v);
}

}  // namespace

LinePlot& LinePlot::SetTitle(std::string title) {
  title_ = std::move(title);
  return *this;
}

LinePlot& LinePlot::SetXLabel(std::string label, std::string unit) {
  x_label_ = svg::WithUnit(label, unit);
  return *this;
}

LinePlot& LinePlot::SetYLabel(std::string label, std::string unit) {
  y_label_ = svg::WithUnit(label, unit);
  return *this;
}

LinePlot& LinePlot::AddSeries(std::string name, std::span<const double> x,
                              std::span<const double> y, SeriesStyle style) {
  if (name.empty()) throw InputError("LinePlot::AddSeries: series name is empty");
  if (x.size() != y.size()) {
    throw InputError("LinePlot::AddSeries: series '" + name + "' has " + std::to_string(x.size()) +
                     " x values but " + std::to_string(y.size()) + " y values");
  }
  if (!style.line && !style.markers) {
    throw InputError("LinePlot::AddSeries: series '" + name + "' draws neither line nor markers");
  }
  series_.push_back({std::move(name), {x.begin(), x.end()}, {y.begin(), y.end()}, style});
  return *this;
}

LinePlot& LinePlot::AddSeries(std::string name, const Eigen::Ref<const Eigen::VectorXd>& x,
                              const Eigen::Ref<const Eigen::VectorXd>& y, SeriesStyle style) {
  return AddSeries(std::move(name), std::span<const double>(x.data(), x.size()),
                   std::span<const double>(y.data(), y.size()), std::move(style));
}

LinePlot& LinePlot::SetXRange(double lo, double hi) {
  CheckRange("SetXRange", lo, hi);
  x_range_ = Range{lo, hi};
  return *this;
}

LinePlot& LinePlot::SetYRange(double lo, double hi) {
  CheckRange("SetYRange", lo, hi);
  y_range_ = Range{lo, hi};
  return *this;
}

LinePlot& LinePlot::AddBand(double lo, double hi, std::string label, std::string color) {
  if (std::isnan(lo) || std::isnan(hi) || !(lo < hi)) {
    throw InputError("LinePlot::AddBand: band '" + label + "' [" + svg::Short(lo) + ", " +
                     svg::Short(hi) + "] needs lo < hi");
  }
  bands_.push_back({lo, hi, std::move(label), std::move(color)});
  return *this;
}

LinePlot& LinePlot::AddVerticalLine(double x, std::string label, std::string color) {
  if (!std::isfinite(x)) {
    throw InputError("LinePlot::AddVerticalLine: line '" + label + "' at x = " + svg::Short(x) +
                     " is not finite");
  }
  lines_.push_back({x, std::move(label), std::move(color)});
  return *this;
}

LinePlot& LinePlot::SetLegendPlacement(LegendPlacement placement) {
  legend_ = placement;
  return *this;
}

std::string LinePlot::ToSvg(int width, int height) const {
  if (width < kMinWidth || height < kMinHeight) {
    throw InputError("LinePlot::ToSvg: canvas " + std::to_string(width) + " x " +
                     std::to_string(height) + " px is smaller than the minimum " +
                     std::to_string(kMinWidth) + " x " + std::to_string(kMinHeight) + " px");
  }
  const LayoutRequest request;
  const LinePlotLayout layout = Layout(width, height, request);
  std::string out = svg::DocumentStart(width, height);
  Render(out, layout, request, std::string(svg::kIdPlaceholder));
  out += svg::kDocumentEnd;
  svg::ResolveIds(out);
  return out;
}

void LinePlot::WriteSvg(const std::string& path, int width, int height) const {
  WriteFileAtomically(path, ToSvg(width, height));
}

std::optional<Range> LinePlot::XExtent() const {
  if (x_range_) return x_range_;
  std::optional<Range> r;
  for (const Series& s : series_) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (std::isfinite(s.y[i])) Grow(r, s.x[i]);
    }
  }
  for (const Band& b : bands_) {
    Grow(r, b.lo);
    Grow(r, b.hi);
  }
  for (const VerticalLine& l : lines_) Grow(r, l.x);
  return r;
}

std::optional<Range> LinePlot::YExtent(double x_lo, double x_hi) const {
  std::optional<Range> r;
  for (const Series& s : series_) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (s.x[i] >= x_lo && s.x[i] <= x_hi) Grow(r, s.y[i]);
    }
  }
  return r;
}

bool LinePlot::HasData() const {
  for (const Series& s : series_) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) return true;
    }
  }
  return false;
}

std::size_t LinePlot::PaletteIndex(std::size_t series) const {
  std::size_t index = 0;
  for (std::size_t i = 0; i < series; ++i) index += series_[i].style.color.empty();
  return index;
}

std::string LinePlot::ColorOf(std::size_t series) const { return StyleOf(series).color; }

SeriesStyle LinePlot::StyleOf(std::size_t series) const {
  const SeriesStyle& style = series_[series].style;
  return style.color.empty() ? PaletteStyle(style, PaletteIndex(series)) : style;
}

SeriesStyle PaletteStyle(SeriesStyle style, std::size_t index) {
  if (index / svg::kSeriesColorCount % 2 == 1)
    style.dash = style.dash == Dash::kDotted ? Dash::kSolid : Dash::kDotted;
  style.color = std::string(svg::SeriesColor(index));
  return style;
}

}  // namespace usvid
