// summary.md as report.html shows it (markdown_html.h): tables with a header row and inline
// markup in cells, lists, paragraphs, the title left to the page, and every text HTML-escaped.
#include "harness/markdown_html.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace usvid {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// The row above `| --- |` is a header of <th>; cells are trimmed and `**bold**` is <strong>,
// with no asterisks left over.
TEST(MarkdownHtmlTest, TableHeaderRowAndBoldCell) {
  const std::string html =
      MarkdownToHtml("| method | fit |\n| --- | ---: |\n| **eb-lr** | 93.1 ± 0.2 |\n");
  EXPECT_THAT(html, HasSubstr("<thead>\n<tr><th>method</th><th>fit</th></tr>\n</thead>"));
  EXPECT_THAT(html, HasSubstr("<tr><td><strong>eb-lr</strong></td><td>93.1 ± 0.2</td></tr>"));
  EXPECT_THAT(html, Not(HasSubstr("*")));
  EXPECT_THAT(html, Not(HasSubstr("---")));
}

// `\|` is a pipe inside its cell, not a cell boundary; `*em*` and `code` render in cells.
TEST(MarkdownHtmlTest, EscapedPipeStaysInCell) {
  const std::string html = MarkdownToHtml("| a | b |\n| --- | --- |\n| x \\| y | *e* `c` |\n");
  EXPECT_THAT(html, HasSubstr("<td>x | y</td><td><em>e</em> <code>c</code></td></tr>"));
}

// The document's `# ` title is dropped by default (the page writes its own <h1>), kept on
// request; other headings stay.
TEST(MarkdownHtmlTest, TitleSkippedUnlessKept) {
  const std::string md = "# usvid compare: s\n\n## msd\n\ntext\n";
  const std::string skipped = MarkdownToHtml(md, {.skip_title = true});
  EXPECT_THAT(skipped, Not(HasSubstr("<h1>")));
  EXPECT_THAT(skipped, Not(HasSubstr("usvid compare")));
  EXPECT_THAT(skipped, HasSubstr("<h2>msd</h2>"));
  EXPECT_EQ(MarkdownToHtml(md), skipped);
  EXPECT_THAT(MarkdownToHtml(md, {.skip_title = false}), HasSubstr("<h1>usvid compare: s</h1>"));
}

// HTML special characters in text, cells and code spans are escaped, never passed through.
TEST(MarkdownHtmlTest, SpecialCharactersEscaped) {
  const std::string html = MarkdownToHtml("a < b & c\n\n| `<x>` | R&D |\n");
  EXPECT_THAT(html, HasSubstr("<p>a &lt; b &amp; c</p>"));
  EXPECT_THAT(html, HasSubstr("<td><code>&lt;x&gt;</code></td><td>R&amp;D</td>"));
  EXPECT_THAT(html, Not(HasSubstr("<x>")));
}

// Consecutive `- ` lines are one <ul>; items and paragraphs render their inline markup, and a
// lone star between spaces stays a star.
TEST(MarkdownHtmlTest, ListAndParagraphInlineMarkup) {
  const std::string html = MarkdownToHtml(
      "Best for gp: **zigzag** (2 * 3).\n\n- msd / steps / **gp**: failed\n- b\nafter\n");
  EXPECT_THAT(html, HasSubstr("<p>Best for gp: <strong>zigzag</strong> (2 * 3).</p>"));
  EXPECT_THAT(html, HasSubstr("<ul>\n<li>msd / steps / <strong>gp</strong>: failed</li>\n"
                              "<li>b</li>\n</ul>\n<p>after</p>"));
}

}  // namespace
}  // namespace usvid
