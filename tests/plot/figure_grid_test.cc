// FigureGrid: stacked panels share one x axis, their plot areas line up, x tick labels and the
// x-axis label appear once under the bottom panel, repeated legends are left out.
#include "plot/figure_grid.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/error.h"
#include "tests/plot/svg_inspect.h"
#include "tests/plot/xml_check.h"

namespace usvid {
namespace {

using svg_inspect::Num;
using ::testing::HasSubstr;

class FigureGridTest : public ::testing::Test {
 protected:
  LinePlot Channel(const std::string& y_label, double t_end, double scale) const {
    std::vector<double> t;
    std::vector<double> y;
    for (int i = 0; i <= 100; ++i) {
      t.push_back(t_end * i / 100.0);
      y.push_back(scale * std::sin(i * 0.1));
    }
    LinePlot p;
    p.SetYLabel(y_label).SetXLabel("own label");
    p.AddSeries("measured", t, y).AddSeries("model", t, y, SeriesStyle::Dashed());
    return p;
  }
};

// Three panels of different y scales and x extents: well formed, one clip rectangle per panel
// with equal left edge and width, and the x range is the union (0..120).
TEST_F(FigureGridTest, PanelsShareTheXAxisAndAlign) {
  FigureGrid grid;
  grid.SetTitle("run 7").SetXLabel("time", "s");
  grid.Add(Channel("u [m/s]", 100, 3)).Add(Channel("v [m/s]", 120, 0.3));
  grid.Add(Channel("r [deg/s]", 110, 12000));
  const xml_check::Document doc = xml_check::Parse(grid.ToSvg(900, 700));
  ASSERT_TRUE(doc.Ok()) << doc.error;
  const auto clips = doc.Within("rect", [](const auto& e) {
    return e.name == "clipPath" && e.Attr("id").ends_with("-area");
  });
  ASSERT_EQ(clips.size(), 3u);
  for (const auto* c : clips) {
    EXPECT_EQ(Num(*c, "x"), Num(*clips[0], "x"));
    EXPECT_EQ(Num(*c, "width"), Num(*clips[0], "width"));
  }
  std::vector<std::string> ids;
  for (const auto* c : doc.Named("clipPath")) ids.push_back(c->Attr("id"));
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(std::unique(ids.begin(), ids.end()), ids.end());

  const std::vector<std::string> ticks = svg_inspect::TextsOfClass(doc, "ticks");
  EXPECT_EQ(std::count(ticks.begin(), ticks.end(), "120"), 1);
  EXPECT_EQ(std::count(ticks.begin(), ticks.end(), "0"), 4);  // three y axes, one x axis
  std::vector<std::string> texts;
  for (const auto* t : doc.Named("text")) texts.push_back(t->text);
  EXPECT_EQ(std::count(texts.begin(), texts.end(), "time [s]"), 1);
  EXPECT_EQ(std::count(texts.begin(), texts.end(), "own label"), 0);
  EXPECT_EQ(std::count(texts.begin(), texts.end(), "run 7"), 1);
}

// A legend equal to the one above is left out; a different one is drawn.
TEST_F(FigureGridTest, RepeatedLegendsAreLeftOut) {
  FigureGrid grid;
  LinePlot other = Channel("r", 100, 1);
  other.AddSeries("rudder", std::vector<double>{0, 1}, std::vector<double>{0, 1});
  grid.Add(Channel("u", 100, 1)).Add(Channel("v", 100, 1)).Add(other);
  const xml_check::Document doc = xml_check::Parse(grid.ToSvg(900, 600));
  ASSERT_TRUE(doc.Ok()) << doc.error;
  const std::vector<std::string> legend = svg_inspect::TextsOfClass(doc, "legend");
  EXPECT_EQ(legend, (std::vector<std::string>{"measured", "model", "measured", "model", "rudder"}));
}

// Bad input throws InputError naming the problem.
TEST_F(FigureGridTest, BadArgumentsThrowInputError) {
  FigureGrid grid;
  EXPECT_THROW((void)grid.ToSvg(800, 600), InputError);
  EXPECT_THROW(grid.Add(LinePlot(), 0.0), InputError);
  grid.Add(LinePlot()).Add(LinePlot());
  try {
    (void)grid.ToSvg(800, 100);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("minimum 240 x 120 px for 2 panels"));
  }
}

}  // namespace
}  // namespace usvid
