// HeatMap: a well-formed SVG whose cells print their values (n/a for NaN), take viridis colours
// over the value range, explain them with a colour bar, escape text, and reject bad input.
#include "plot/heat_map.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "plot/colors.h"
#include "tests/plot/svg_inspect.h"
#include "tests/plot/xml_check.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

class HeatMapTest : public ::testing::Test {
 protected:
  HeatMapTest() : values_(4, 3) {
    values_ << 92.4, 81.0, 67.3, 95.1, 88.7, 74.9, 78.2, kNaN, 41.5, 97.3, 90.2, -12.4;
  }
  HeatMap Make() const {
    return HeatMap({"least squares", "EKF", "SINDy", "neural ODE"},
                   {"zigzag 20/20", "turning circle", "pull-out"}, values_);
  }
  // The cells of `doc` (which must outlive them) in document order, row by row.
  struct Cell {
    const xml_check::Element* rect = nullptr;
    std::string text;
  };
  static std::vector<Cell> Cells(const xml_check::Document& doc) {
    std::vector<Cell> cells;
    for (std::size_t i = 0; i < doc.elements.size(); ++i) {
      if (doc.elements[i].Attr("class") != "cell") continue;
      Cell cell;
      for (std::size_t j = i + 1; j < doc.elements.size(); ++j) {
        const xml_check::Element& e = doc.elements[j];
        if (e.parent != static_cast<int>(i)) continue;
        if (e.name == "rect") cell.rect = &e;
        if (e.name == "text") cell.text = e.text;
      }
      cells.push_back(cell);
    }
    return cells;
  }

  Eigen::MatrixXd values_;
};

// Title, labels, cells and colour bar together give balanced tags under one <svg> root.
TEST_F(HeatMapTest, ProducesWellFormedSvg) {
  HeatMap map = Make();
  map.SetTitle("Fit").SetAxisLabels("method", "test maneuver").SetValueLabel("fit", "%");
  const xml_check::Document doc = xml_check::Parse(map.ToSvg(700, 420));
  ASSERT_TRUE(doc.Ok()) << doc.error;
  EXPECT_EQ(doc.elements[0].name, "svg");
  EXPECT_EQ(doc.elements[0].Attr("viewBox"), "0 0 700 420");
}

// Each of the 4 x 3 cells prints its value with the chosen decimals, row by row.
TEST_F(HeatMapTest, CellsCarryTheirPrintedValues) {
  const xml_check::Document doc = xml_check::Parse(Make().ToSvg(700, 420));
  const std::vector<Cell> cells = Cells(doc);
  ASSERT_EQ(cells.size(), 12u);
  EXPECT_EQ(cells[0].text, "92.4");
  EXPECT_EQ(cells[1].text, "81.0");
  EXPECT_EQ(cells[11].text, "\u221212.4");
  EXPECT_EQ(cells[8].text, "41.5");
}

// The NaN cell reads "n/a" and is filled with the hatch pattern, which the document defines.
TEST_F(HeatMapTest, NanCellReadsNotAvailableAndIsHatched) {
  const xml_check::Document doc = xml_check::Parse(Make().ToSvg(700, 420));
  const std::vector<Cell> cells = Cells(doc);
  ASSERT_EQ(cells.size(), 12u);
  const Cell& nan = cells[2 * 3 + 1];
  EXPECT_EQ(nan.text, "n/a");
  ASSERT_NE(nan.rect, nullptr);
  const auto patterns = doc.Named("pattern");
  ASSERT_EQ(patterns.size(), 1u);
  EXPECT_EQ(nan.rect->Attr("fill"), "url(#" + patterns[0]->Attr("id") + ")");
  const int na = static_cast<int>(
      std::count_if(cells.begin(), cells.end(), [](const Cell& c) { return c.text == "n/a"; }));
  EXPECT_EQ(na, 1);
}

// Fills follow viridis over the value range: the ends of the range take its end colours and a
// value below a fixed range takes the low end.
TEST_F(HeatMapTest, FillsFollowTheColourScale) {
  const xml_check::Document doc = xml_check::Parse(Make().ToSvg(700, 420));
  const std::vector<Cell> cells = Cells(doc);
  EXPECT_EQ(cells[9].rect->Attr("fill"), svg::Hex(svg::Viridis(1.0)));   // 97.3, the maximum
  EXPECT_EQ(cells[11].rect->Attr("fill"), svg::Hex(svg::Viridis(0.0)));  // -12.4, the minimum

  HeatMap fixed = Make();
  fixed.SetValueRange(0.0, 100.0);
  const xml_check::Document fixed_doc = xml_check::Parse(fixed.ToSvg(700, 420));
  const std::vector<Cell> fixed_cells = Cells(fixed_doc);
  EXPECT_EQ(fixed_cells[11].rect->Attr("fill"), svg::Hex(svg::Viridis(0.0)));
  EXPECT_EQ(fixed_cells[0].rect->Attr("fill"), svg::Hex(svg::Viridis(0.924)));
}

// With the range 0..100 the colour bar is labelled at 0, 20, ..., 100 and by its label.
TEST_F(HeatMapTest, ColorBarShowsNiceTicksOfTheRange) {
  HeatMap map = Make();
  map.SetValueRange(0.0, 100.0).SetValueLabel("fit", "%");
  const xml_check::Document doc = xml_check::Parse(map.ToSvg(700, 420));
  const std::vector<std::string> bar = svg_inspect::TextsOfClass(doc, "color-bar");
  EXPECT_EQ(bar, (std::vector<std::string>{"0", "20", "40", "60", "80", "100", "fit [%]"}));
  EXPECT_EQ(doc.Named("linearGradient").size(), 1u);
}

// Decimals and suffix, or a formatter, decide the cell text; NaN always reads "n/a".
TEST_F(HeatMapTest, FormatIsConfigurable) {
  HeatMap map = Make();
  map.SetDecimals(0, " %");
  EXPECT_EQ(map.FormatValue(92.4), "92 %");
  EXPECT_EQ(map.FormatValue(-3.6), "\u22124 %");
  map.SetFormatter([](double v) { return v > 90 ? "good" : "poor"; });
  EXPECT_EQ(map.FormatValue(92.4), "good");
  EXPECT_EQ(map.FormatValue(kNaN), "n/a");
  const xml_check::Document doc = xml_check::Parse(map.ToSvg(700, 420));
  EXPECT_EQ(Cells(doc)[1].text, "poor");
}

// Markup in labels and title is escaped and reads back unchanged.
TEST_F(HeatMapTest, TextIsXmlEscaped) {
  HeatMap map({"a<b"}, {"c&d", "\"e\""}, Eigen::RowVector2d(1.0, 2.0));
  map.SetTitle("<title>").SetAxisLabels("x'y", "</g>");
  const std::string svg = map.ToSvg(400, 300);
  const xml_check::Document doc = xml_check::Parse(svg);
  ASSERT_TRUE(doc.Ok()) << doc.error;
  std::vector<std::string> texts;
  for (const auto* t : doc.Named("text")) texts.push_back(t->text);
  for (const char* s : {"a<b", "c&d", "\"e\"", "<title>", "x'y", "</g>"}) {
    EXPECT_NE(std::find(texts.begin(), texts.end(), s), texts.end()) << s;
  }
  EXPECT_THAT(svg, HasSubstr("a&lt;b"));
}

// Column labels wider than their cells are turned by 45 degrees.
TEST_F(HeatMapTest, LongColumnLabelsAreRotated) {
  HeatMap narrow({"r"}, {"a rather long maneuver name", "another long maneuver name"},
                 Eigen::RowVector2d(1.0, 2.0));
  const xml_check::Document doc = xml_check::Parse(narrow.ToSvg(300, 300));
  const auto labels = svg_inspect::InClass(doc, "text", "column-labels");
  ASSERT_EQ(labels.size(), 2u);
  EXPECT_THAT(labels[0]->Attr("transform"), HasSubstr("rotate(-45"));
  const auto wide = xml_check::Parse(Make().ToSvg(900, 420));
  for (const auto* t : svg_inspect::InClass(wide, "text", "column-labels")) {
    EXPECT_EQ(t->Attr("transform"), "");
  }
}

// Bad input throws InputError with a message naming what is wrong.
TEST_F(HeatMapTest, BadArgumentsThrowInputError) {
  EXPECT_THAT(svg_inspect::InputErrorOf([&] {
                HeatMap({"a"}, {"b", "c"}, values_);
              }),
              HasSubstr("1 row labels and 2 column labels for a 4 x 3 value matrix"));
  EXPECT_THAT(svg_inspect::InputErrorOf([] { HeatMap({}, {}, Eigen::MatrixXd(0, 0)); }),
              HasSubstr("empty"));
  HeatMap map = Make();
  EXPECT_THAT(svg_inspect::InputErrorOf([&] { map.SetValueRange(5.0, 5.0); }),
              HasSubstr("SetValueRange"));
  EXPECT_THAT(svg_inspect::InputErrorOf([&] { map.SetDecimals(-1); }), HasSubstr("decimals = -1"));
  EXPECT_THAT(svg_inspect::InputErrorOf([&] { (void)map.ToSvg(0, 0); }),
              HasSubstr("canvas 0 x 0 px"));
}

}  // namespace
}  // namespace usvid
