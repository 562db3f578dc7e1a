// LinePlot: a well-formed SVG whose pixels sit where the values say, with nice ticks, gaps at
// NaN, visible spikes after decimation, escaped text, and InputError for bad arguments.
#include "plot/svg_plot.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "core/error.h"
#include "plot/colors.h"
#include "tests/plot/svg_inspect.h"
#include "tests/plot/xml_check.h"

namespace usvid {
namespace {

using svg_inspect::Num;
using ::testing::HasSubstr;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kWidth = 800;
constexpr int kHeight = 500;

class LinePlotTest : public ::testing::Test {
 protected:
  // Parses plot_.ToSvg(kWidth, kHeight), failing the test when it is not well formed.
  xml_check::Document Render() {
    svg_ = plot_.ToSvg(kWidth, kHeight);
    xml_check::Document doc = xml_check::Parse(svg_);
    EXPECT_TRUE(doc.Ok()) << doc.error;
    layout_ = plot_.Layout(kWidth, kHeight, LayoutRequest{});
    return doc;
  }
  double Px(double x) const {
    return layout_.area_left +
           (x - layout_.x.lo) / (layout_.x.hi - layout_.x.lo) * layout_.area_width;
  }
  double Py(double y) const {
    return layout_.area_top +
           (layout_.y.hi - y) / (layout_.y.hi - layout_.y.lo) * layout_.area_height;
  }

  LinePlot plot_;
  std::string svg_;
  LinePlotLayout layout_;
};

// Every feature at once still gives balanced tags and an <svg> root of the requested size.
TEST_F(LinePlotTest, ProducesWellFormedSvg) {
  const std::vector<double> x = {0, 1, 2, 3, 4, 5};
  const std::vector<double> y = {1, 3, kNaN, 2, 5, 4};
  plot_.SetTitle("Surge").SetXLabel("time", "s").SetYLabel("u", "m/s");
  plot_.AddSeries("measured", x, y, SeriesStyle::LineAndMarkers());
  plot_.AddSeries("model", x, y, SeriesStyle::Dashed());
  plot_.AddBand(1, 2, "regime").AddVerticalLine(3.5, "event");
  const xml_check::Document doc = Render();
  ASSERT_FALSE(doc.elements.empty());
  EXPECT_EQ(doc.elements[0].name, "svg");
  EXPECT_EQ(doc.elements[0].Attr("width"), "800");
  EXPECT_EQ(doc.elements[0].Attr("height"), "500");
  EXPECT_EQ(doc.elements[0].Attr("xmlns"), "http://www.w3.org/2000/svg");
}

// Axis limits are ticks, ticks step by 1, 2 or 5 times a power of ten and cover the data, and
// every tick label is printed.
TEST_F(LinePlotTest, AxisTicksAreNiceAndCoverTheData) {
  const std::vector<double> x = {0.0, 3.1, 9.3};
  const std::vector<double> y = {-0.37, 2.71, 1.0};
  plot_.AddSeries("s", x, y);
  const xml_check::Document doc = Render();
  for (const svg::AxisTicks* t : {&layout_.x, &layout_.y}) {
    const double mantissa = t->step / std::pow(10.0, std::floor(std::log10(t->step) + 1e-9));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
                std::abs(mantissa - 5) < 1e-9)
        << t->step;
    EXPECT_DOUBLE_EQ(t->lo, t->values.front());
    EXPECT_DOUBLE_EQ(t->hi, t->values.back());
    EXPECT_GE(t->values.size(), 3u);
  }
  EXPECT_LE(layout_.x.lo, 0.0);
  EXPECT_GE(layout_.x.hi, 9.3);
  EXPECT_LE(layout_.y.lo, -0.37);
  EXPECT_GE(layout_.y.hi, 2.71);
  const std::vector<std::string> printed = svg_inspect::TextsOfClass(doc, "ticks");
  for (const auto& label : layout_.y.labels) {
    EXPECT_NE(std::find(printed.begin(), printed.end(), label), printed.end()) << label;
  }
  EXPECT_NE(std::find(printed.begin(), printed.end(), "\u22120.5"), printed.end());
}

// A marker and the path vertices are drawn at the pixels that the axis limits map them to.
TEST_F(LinePlotTest, PointPixelPositionMatchesItsValue) {
  const std::vector<double> x = {0.0, 2.0, 10.0};
  const std::vector<double> y = {0.0, 3.0, 8.0};
  plot_.AddSeries("s", x, y, SeriesStyle::LineAndMarkers());
  const xml_check::Document doc = Render();
  const auto circles = svg_inspect::SeriesElements(doc, "s", "circle");
  ASSERT_EQ(circles.size(), 3u);
  EXPECT_NEAR(Num(*circles[1], "cx"), Px(2.0), 0.01);
  EXPECT_NEAR(Num(*circles[1], "cy"), Py(3.0), 0.01);
  const auto paths = svg_inspect::SeriesElements(doc, "s", "path");
  ASSERT_EQ(paths.size(), 1u);
  const auto lines = svg_inspect::PathPolylines(paths[0]->Attr("d"));
  ASSERT_EQ(lines.size(), 1u);
  ASSERT_EQ(lines[0].size(), 3u);
  EXPECT_NEAR(lines[0][2].first, Px(10.0), 0.01);
  EXPECT_NEAR(lines[0][2].second, Py(8.0), 0.01);
}

// NaN samples (unsampled) end the line: two gaps give three separate subpaths, and a lone
// sample between gaps is still shown, as a dot.
TEST_F(LinePlotTest, NanBreaksTheLineIntoSegments) {
  const std::vector<double> x = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  const std::vector<double> y = {1, 2, kNaN, 3, 4, kNaN, 5, 6, 7};
  plot_.AddSeries("s", x, y);
  const std::vector<double> lone = {kNaN, 2, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN};
  plot_.AddSeries("lone", x, lone);
  const xml_check::Document doc = Render();
  const auto paths = svg_inspect::SeriesElements(doc, "s", "path");
  ASSERT_EQ(paths.size(), 1u);
  const auto lines = svg_inspect::PathPolylines(paths[0]->Attr("d"));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].size(), 2u);
  EXPECT_EQ(lines[1].size(), 2u);
  EXPECT_EQ(lines[2].size(), 3u);
  EXPECT_NEAR(lines[1][0].first, Px(3.0), 0.01);
  const auto dots = svg_inspect::SeriesElements(doc, "lone", "circle");
  ASSERT_EQ(dots.size(), 1u);
  EXPECT_NEAR(Num(*dots[0], "cy"), Py(2.0), 0.01);
}

// 100k samples are drawn with at most a few thousand vertices, and a one-sample spike and dip
// are still drawn at their full values.
TEST_F(LinePlotTest, DecimationKeepsTheExtremesOfLongSeries) {
  const int n = 100000;
  std::vector<double> x(n);
  std::vector<double> y(n);
  for (int i = 0; i < n; ++i) {
    x[i] = i * 0.01;
    y[i] = std::sin(i * 0.001);
  }
  y[54321] = 10.0;
  y[77777] = -7.0;
  plot_.AddSeries("long", x, y);
  const xml_check::Document doc = Render();
  const auto paths = svg_inspect::SeriesElements(doc, "long", "path");
  ASSERT_EQ(paths.size(), 1u);
  const auto lines = svg_inspect::PathPolylines(paths[0]->Attr("d"));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_LE(lines[0].size(), static_cast<std::size_t>(4 * kWidth));
  double top = 1e9;
  double bottom = -1e9;
  for (const auto& [px, py] : lines[0]) {
    top = std::min(top, py);
    bottom = std::max(bottom, py);
  }
  EXPECT_NEAR(top, Py(10.0), 0.01);
  EXPECT_NEAR(bottom, Py(-7.0), 0.01);
}

// Markup characters in every kind of text are escaped and read back unchanged.
TEST_F(LinePlotTest, TextIsXmlEscaped) {
  const std::vector<double> x = {0, 1};
  plot_.SetTitle("a<b & \"c\"").SetXLabel("x's", "m<s").SetYLabel("y&", "");
  plot_.AddSeries("<script>alert(1)</script>", x, x).AddBand(0, 0.5, "<band>");
  plot_.AddVerticalLine(0.7, "</svg>");
  const xml_check::Document doc = Render();
  EXPECT_THAT(svg_, HasSubstr("a&lt;b &amp; &quot;c&quot;"));
  EXPECT_THAT(svg_, ::testing::Not(HasSubstr("<script>")));
  std::set<std::string> texts;
  for (const auto* t : doc.Named("text")) texts.insert(t->text);
  for (const char* s :
       {"a<b & \"c\"", "x's [m<s]", "y&", "<script>alert(1)</script>", "<band>", "</svg>"}) {
    EXPECT_EQ(texts.count(s), 1u) << s;
  }
}

// The legend sits right of the plot area; with long names it moves below the plot area.
TEST_F(LinePlotTest, LegendStaysOutsideThePlotArea) {
  const std::vector<double> x = {0, 1};
  plot_.AddSeries("measured", x, x);
  xml_check::Document doc = Render();
  const auto right = svg_inspect::InClass(doc, "text", "legend");
  ASSERT_EQ(right.size(), 1u);
  EXPECT_GT(Num(*right[0], "x"), layout_.area_left + layout_.area_width);

  plot_.AddSeries("a very long series name that would take far too much room on the right", x, x);
  doc = Render();
  EXPECT_FALSE(layout_.legend_right);
  const auto below = svg_inspect::InClass(doc, "text", "legend");
  ASSERT_EQ(below.size(), 2u);
  for (const auto* t : below) {
    EXPECT_GT(Num(*t, "y"), layout_.area_top + layout_.area_height + 20.0);
    EXPECT_LT(Num(*t, "y"), kHeight);
  }
}

// Series without a colour take distinct palette colours; a given colour is used as is.
TEST_F(LinePlotTest, SeriesTakeDistinctColours) {
  const std::vector<double> x = {0, 1};
  const std::vector<std::string> names = {"s0", "s1", "s2", "s3", "s4", "s5"};
  for (const std::string& name : names) plot_.AddSeries(name, x, x);
  plot_.AddSeries("gray", x, x, SeriesStyle{.color = "#777777"});
  const xml_check::Document doc = Render();
  std::set<std::string> colours;
  for (const std::string& name : names) {
    const auto paths = svg_inspect::SeriesElements(doc, name, "path");
    ASSERT_EQ(paths.size(), 1u);
    colours.insert(paths[0]->Attr("stroke"));
  }
  EXPECT_EQ(colours.size(), 6u);
  EXPECT_EQ(svg_inspect::SeriesElements(doc, "gray", "path")[0]->Attr("stroke"), "#777777");
}

// Measured data drawn with SeriesStyle::Measured keep a colour no model series takes, even
// when the models outnumber the palette (the KVLCC2 study plots the data and eight models).
TEST_F(LinePlotTest, MeasuredDataKeepAColourNoModelTakes) {
  const std::vector<double> x = {0, 1};
  plot_.AddSeries("measured", x, x, SeriesStyle::Measured());
  for (int i = 0; i < 9; ++i) plot_.AddSeries("m" + std::to_string(i), x, x, SeriesStyle::Dashed());
  const xml_check::Document doc = Render();
  const std::string data = svg_inspect::SeriesElements(doc, "measured", "path")[0]->Attr("stroke");
  for (int i = 0; i < 9; ++i)
    EXPECT_NE(svg_inspect::SeriesElements(doc, "m" + std::to_string(i), "path")[0]->Attr("stroke"),
              data)
        << i;
}

// When the models outnumber the palette, a colour's second series is dotted where its first is
// dashed (the real suite's Esso Osaka track plots nine: refit took diagnose's blue, SINDy
// fossen-ceres's orange, both dashed), in the plot and in the legend.
TEST_F(LinePlotTest, AColoursSecondSeriesIsDrawnDotted) {
  const std::vector<double> x = {0, 1};
  const std::size_t n = svg::kSeriesColorCount + 2;
  for (std::size_t i = 0; i < n; ++i)
    plot_.AddSeries("m" + std::to_string(i), x, x, SeriesStyle::Dashed());
  const xml_check::Document doc = Render();
  const auto path = [&](std::size_t i) {
    return svg_inspect::SeriesElements(doc, "m" + std::to_string(i), "path")[0];
  };
  for (std::size_t i = 0; i < svg::kSeriesColorCount; ++i)
    EXPECT_EQ(path(i)->Attr("stroke-dasharray"), "7 4") << i;
  for (std::size_t i = svg::kSeriesColorCount; i < n; ++i) {
    EXPECT_EQ(path(i)->Attr("stroke"), path(i - svg::kSeriesColorCount)->Attr("stroke")) << i;
    EXPECT_EQ(path(i)->Attr("stroke-dasharray"), "1.5 3") << i;
  }
  // The legend's swatches: two dotted lines.
  int dotted_swatches = 0;
  for (const auto& e : doc.elements)
    dotted_swatches += e.name == "line" && e.Attr("stroke-dasharray") == "1.5 3";
  EXPECT_EQ(dotted_swatches, 2);
}

// A figure that gives each method its colour itself (compare's free-run figures) gets the same
// rule: the palette's second round dotted, its third as the first.
TEST(PaletteStyleTest, EveryOtherRoundOfThePaletteChangesTheDash) {
  const std::size_t n = svg::kSeriesColorCount;
  EXPECT_EQ(PaletteStyle(SeriesStyle::Dashed(), 1).dash, Dash::kDashed);
  EXPECT_EQ(PaletteStyle(SeriesStyle::Dashed(), n + 1).dash, Dash::kDotted);
  EXPECT_EQ(PaletteStyle(SeriesStyle::Dashed(), n + 1).color,
            PaletteStyle(SeriesStyle::Dashed(), 1).color);
  EXPECT_EQ(PaletteStyle(SeriesStyle::Dotted(), n).dash, Dash::kSolid);
  EXPECT_EQ(PaletteStyle(SeriesStyle::Dashed(), 2 * n).dash, Dash::kDashed);
}

// A fixed y range is kept as the axis limits; the data beyond it are clipped to the plot area.
TEST_F(LinePlotTest, FixedYRangeIsKeptAndDataAreClipped) {
  const std::vector<double> x = {0, 1, 2};
  const std::vector<double> y = {-5, 0.3, 5};
  plot_.AddSeries("s", x, y).SetYRange(-1.0, 1.0);
  const xml_check::Document doc = Render();
  EXPECT_DOUBLE_EQ(layout_.y.lo, -1.0);
  EXPECT_DOUBLE_EQ(layout_.y.hi, 1.0);
  // The line's group is clipped by a clip path whose rectangle is the plot area.
  const auto path = svg_inspect::SeriesElements(doc, "s", "path");
  ASSERT_EQ(path.size(), 1u);
  std::string clip_url;
  for (int p = path[0]->parent; p >= 0 && clip_url.empty(); p = doc.elements[p].parent) {
    clip_url = doc.elements[p].Attr("clip-path");
  }
  const auto rects = doc.Within("rect", [](const auto& e) { return e.name == "clipPath"; });
  const auto area = std::find_if(rects.begin(), rects.end(), [&](const auto* r) {
    return clip_url == "url(#" + doc.elements[r->parent].Attr("id") + ")";
  });
  ASSERT_NE(area, rects.end()) << clip_url;
  EXPECT_NEAR(Num(**area, "y"), layout_.area_top, 0.01);
  EXPECT_NEAR(Num(**area, "height"), layout_.area_height, 0.01);
}

// Bands are shaded over their x interval and, like reference lines, labelled above the plot
// area; an infinite band edge reaches the edge of the plot.
TEST_F(LinePlotTest, BandsAndReferenceLinesAreLabelledAboveThePlotArea) {
  const std::vector<double> x = {0, 12};
  plot_.AddSeries("s", x, x);
  plot_.AddBand(0, 4, "displacement").AddBand(4, 7, "semi-displacement");
  plot_.AddBand(7, std::numeric_limits<double>::infinity(), "planing");
  plot_.AddVerticalLine(5.2, "hump");
  const xml_check::Document doc = Render();
  const auto bands = doc.Named("rect");
  std::vector<const xml_check::Element*> shaded;
  for (const auto* r : bands) {
    if (r->Attr("class") == "band") shaded.push_back(r);
  }
  ASSERT_EQ(shaded.size(), 3u);
  EXPECT_NEAR(Num(*shaded[1], "x"), Px(4.0), 0.01);
  EXPECT_NEAR(Num(*shaded[1], "width"), Px(7.0) - Px(4.0), 0.02);
  EXPECT_NEAR(Num(*shaded[2], "x") + Num(*shaded[2], "width"), Px(layout_.x.hi), 0.02);
  int labels = 0;
  for (const auto* t : doc.Named("text")) {
    if (t->Attr("class") != "annotation") continue;
    ++labels;
    EXPECT_LT(Num(*t, "y"), layout_.area_top);
  }
  EXPECT_EQ(labels, 4);
}

// Eigen vectors and spans over the same numbers draw the same plot.
TEST_F(LinePlotTest, EigenAndSpanInputsDrawTheSame) {
  const std::vector<double> x = {0, 1, 2};
  const std::vector<double> y = {2, 1, 3};
  LinePlot from_eigen;
  from_eigen.AddSeries("s", Eigen::Vector3d(0, 1, 2), Eigen::Vector3d(2, 1, 3));
  plot_.AddSeries("s", x, y);
  EXPECT_EQ(plot_.ToSvg(kWidth, kHeight), from_eigen.ToSvg(kWidth, kHeight));
}

// Element ids depend on the content, so two plots inlined in one page do not share clip paths.
TEST_F(LinePlotTest, ElementIdsDifferBetweenPlots) {
  const std::vector<double> x = {0, 1};
  const std::vector<double> y = {1, 0};
  LinePlot other;
  other.AddSeries("s", x, y);
  plot_.AddSeries("s", x, x);
  const auto id_of = [](const std::string& svg) {
    return xml_check::Parse(svg).Named("clipPath").at(0)->Attr("id");
  };
  EXPECT_NE(id_of(plot_.ToSvg(kWidth, kHeight)), id_of(other.ToSvg(kWidth, kHeight)));
  EXPECT_EQ(id_of(plot_.ToSvg(kWidth, kHeight)), id_of(plot_.ToSvg(kWidth, kHeight)));
}

// WriteSvg stores exactly ToSvg's text.
TEST_F(LinePlotTest, WriteSvgStoresTheDocument) {
  const std::vector<double> x = {0, 1};
  plot_.AddSeries("s", x, x);
  const auto path = std::filesystem::temp_directory_path() / "usvid_line_plot_test.svg";
  plot_.WriteSvg(path.string(), kWidth, kHeight);
  std::ifstream in(path);
  std::stringstream content;
  content << in.rdbuf();
  EXPECT_EQ(content.str(), plot_.ToSvg(kWidth, kHeight));
  std::filesystem::remove(path);
}

// Bad arguments throw InputError with a message naming what is wrong.
TEST_F(LinePlotTest, BadArgumentsThrowInputError) {
  const std::vector<double> three = {0, 1, 2};
  const std::vector<double> two = {0, 1};
  EXPECT_THAT(svg_inspect::InputErrorOf([&] { plot_.AddSeries("u", three, two); }),
              HasSubstr("series 'u' has 3 x values but 2 y values"));
  EXPECT_THAT(svg_inspect::InputErrorOf([&] { plot_.AddSeries("", two, two); }),
              HasSubstr("name is empty"));
  EXPECT_THAT(svg_inspect::InputErrorOf([&] { plot_.SetYRange(1.0, 1.0); }),
              HasSubstr("SetYRange"));
  EXPECT_THAT(svg_inspect::InputErrorOf([&] { plot_.SetXRange(kNaN, 1.0); }),
              HasSubstr("SetXRange"));
  EXPECT_THAT(svg_inspect::InputErrorOf([&] { plot_.AddBand(2.0, 1.0, "b"); }),
              HasSubstr("band 'b'"));
  EXPECT_THAT(svg_inspect::InputErrorOf([&] { plot_.AddVerticalLine(kNaN, "l"); }),
              HasSubstr("line 'l'"));
  EXPECT_THAT(svg_inspect::InputErrorOf([&] { (void)plot_.ToSvg(0, 400); }),
              HasSubstr("canvas 0 x 400 px"));
  EXPECT_THAT(svg_inspect::InputErrorOf([&] { (void)plot_.ToSvg(400, -1); }),
              HasSubstr("smaller than the minimum 240 x 160 px"));
}

}  // namespace
}  // namespace usvid
