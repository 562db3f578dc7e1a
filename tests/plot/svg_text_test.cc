// SVG text pieces: escaping, compact coordinates, width estimates and content-derived ids.
#include "plot/svg_text.h"

#include <gtest/gtest.h>

#include <cmath>

namespace usvid::svg {
namespace {

class SvgTextTest : public ::testing::Test {};

// The five markup characters become entities; forbidden control characters become '?'.
TEST_F(SvgTextTest, EscapeReplacesMarkupAndControlCharacters) {
  EXPECT_EQ(Escape("a<b>&\"c\"'"), "a&lt;b&gt;&amp;&quot;c&quot;&apos;");
  EXPECT_EQ(Escape(std::string("x\x01y\tz")), "x?y\tz");
  EXPECT_EQ(Escape("ψ [°]"), "ψ [°]");
}

// Coordinates have at most two decimals, no trailing zeros and no negative zero.
TEST_F(SvgTextTest, NumIsCompact) {
  EXPECT_EQ(Num(12.5), "12.5");
  EXPECT_EQ(Num(3.0), "3");
  EXPECT_EQ(Num(-0.001), "0");
  EXPECT_EQ(Num(1.23456), "1.23");
  EXPECT_EQ(Num(NAN), "0");
}

// Wider glyphs and longer strings estimate wider; multi-byte characters count once.
TEST_F(SvgTextTest, TextWidthGrowsWithGlyphs) {
  EXPECT_LT(TextWidth("iii", 12), TextWidth("MMM", 12));
  EXPECT_NEAR(TextWidth("°", 10), TextWidth("a", 10) * 600.0 / 556.0, 1e-9);
  EXPECT_GT(TextWidth("abc", 12, true), TextWidth("abc", 12));
  EXPECT_NEAR(TextWidth("0", 10), 10 * 0.556 * 1.05, 1e-9);
}

// Text that fits is kept; a bit too long shrinks the font; far too long is cut with "…" on a
// code-point boundary.
TEST_F(SvgTextTest, FitTextShrinksThenElides) {
  const FittedText kept = FitText("title", 15, 200);
  EXPECT_EQ(kept.text, "title");
  EXPECT_EQ(kept.font_size, 15);
  const double width = TextWidth("a longer title", 15);
  const FittedText shrunk = FitText("a longer title", 15, width * 0.9);
  EXPECT_EQ(shrunk.text, "a longer title");
  EXPECT_LT(shrunk.font_size, 15);
  const FittedText cut = FitText("ψψψψψψψψψψψψψψψψψψψψ", 15, 60);
  EXPECT_EQ(cut.font_size, 9);
  EXPECT_LE(TextWidth(cut.text, cut.font_size), 60);
  EXPECT_EQ(cut.text.substr(cut.text.size() - 3), "\u2026");
  EXPECT_EQ(cut.text.substr(0, 2), "ψ");
  EXPECT_EQ((cut.text.size() - 3) % 2, 0u);  // whole two-byte code points only
}

// Placeholders become one id that depends on the document.
TEST_F(SvgTextTest, ResolveIdsDependsOnContent) {
  std::string a = "<x id=\"@ID@-a\"/><y ref=\"#@ID@-a\"/>";
  std::string b = "<x id=\"@ID@-a\"/><y ref=\"#@ID@-a\"/><z/>";
  ResolveIds(a);
  ResolveIds(b);
  EXPECT_EQ(a.find("@ID@"), std::string::npos);
  const std::string id = a.substr(7, 17);
  EXPECT_EQ(a, "<x id=\"" + id + "-a\"/><y ref=\"#" + id + "-a\"/>");
  EXPECT_NE(a.substr(0, 24), b.substr(0, 24));
}

}  // namespace
}  // namespace usvid::svg
