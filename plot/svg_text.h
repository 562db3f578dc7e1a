// The text pieces of an SVG document: XML escaping, compact pixel coordinates, and an estimate
// of how wide a label is drawn (Arial/Helvetica metrics, which "Liberation Sans" shares), so
// that layouts keep labels inside the canvas without access to font files. Nothing here throws.
#pragma once

#include <string>
#include <string_view>

namespace usvid::svg {

// The font stack of every usvid plot; the width estimate below is for these metrics.
inline constexpr std::string_view kFontFamily = "Helvetica, Arial, 'Liberation Sans', sans-serif";

// Escapes & < > " ' for element text and attribute values; control characters that XML 1.0
// forbids become '?'.
std::string Escape(std::string_view text);

// A pixel coordinate with at most two decimals and no trailing zeros ("12.5", "-3", "0").
std::string Num(double value);

// A value as printf's %g writes it ("0.001", "1e+06"): the numbers of the plots' error messages.
std::string Short(double value);

// Estimated drawn width [px] of `text` (UTF-8) at `font_size` [px]; `bold` adds about 8 %.
double TextWidth(std::string_view text, double font_size, bool bold = false);

// `text` at `font_size`, shrunk towards `min_font_size` and then cut short with "…" so that
// its estimated width stays within `max_width` (titles and labels on small canvases).
struct FittedText {
  std::string text;
  double font_size = 0.0;
};
FittedText FitText(std::string_view text, double font_size, double max_width, bool bold = false,
                   double min_font_size = 9.0);

enum class Anchor { kStart, kMiddle, kEnd };

// Appends <text x y font-size text-anchor [attributes]>escaped text</text>. `attributes` is
// raw (already escaped) attribute text such as `fill="#333" font-weight="bold"`.
void AppendText(std::string& out, double x, double y, std::string_view text, double font_size,
                Anchor anchor, std::string_view attributes = "");

// The attribute that marks an axis's label (its quantity and unit), so that a reader of the
// figure, a browser test among them (tests/report_render_test.py), finds it.
inline constexpr std::string_view kAxisLabelClass = "class=\"axis-label\"";

// The same text turned by -90 degrees around (x, y), reading bottom to top (y-axis labels).
void AppendVerticalText(std::string& out, double x, double y, std::string_view text,
                        double font_size, std::string_view attributes = "");

// <svg ...> opening tag with size, viewBox and font, plus a white background rectangle.
std::string DocumentStart(int width, int height);
inline constexpr std::string_view kDocumentEnd = "</svg>\n";

// Element ids (clip paths, patterns, gradients) must be unique in an HTML page that inlines
// several plots. Renderers write kIdPlaceholder into ids; ResolveIds replaces it with a hash of
// the finished document, so equal plots get equal ids and different plots different ones.
inline constexpr std::string_view kIdPlaceholder = "@ID@";
void ResolveIds(std::string& document);

// "label [unit]", or just the label when the unit is empty.
std::string WithUnit(std::string_view label, std::string_view unit);

}  // namespace usvid::svg
