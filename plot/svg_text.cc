#include "plot/svg_text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace usvid::svg {
namespace {

// Advance widths of printable ASCII (32..126) in Arial, per 1000 units of the em.
constexpr std::array<int, 95> kArialWidths = {
    278,  278, 355, 556, 556, 889, 667, 191, 333, 333, 389, 584, 278, 333, 278, 278,  // ' '../
    556,  556, 556, 556, 556, 556, 556, 556, 556, 556, 278, 278, 584, 584, 584, 556,  // 0..?
    1015, 667, 667, 722, 722, 667, 611, 778, 722, 278, 500, 667, 556, 833, 722, 778,  // @..O
    667,  778, 722, 667, 611, 722, 667, 944, 667, 667, 611, 278, 278, 278, 469, 556,  // P.._
    333,  556, 556, 500, 556, 556, 278, 556, 556, 222, 222, 500, 222, 833, 556, 556,  // `..o
    556,  556, 333, 500, 278, 556, 500, 722, 500, 500, 500, 334, 260, 334, 584};      // p..~
constexpr int kNonAsciiWidth = 600;
// Fallback fonts (DejaVu Sans) run wider than Arial; estimate on the safe side.
constexpr double kSafety = 1.05;

}  // namespace

std::string Escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default: {
        const auto u = static_cast<unsigned char>(c);
        out += (u < 0x20 && c != '\t' && c != '\n' && c != '\r') ? '?' : c;
      }
    }
  }
  return out;
}

std::string Num(double value) {
  if (!std::isfinite(value)) return "0";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.2f", value);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

std::string Short(double value) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g", value);
  return buf;
}

double TextWidth(std::string_view text, double font_size, bool bold) {
  double units = 0.0;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 32 && u < 127) {
      units += kArialWidths[u - 32];
    } else if ((u & 0xC0) != 0x80 && u >= 0x80) {  // lead byte of a multi-byte code point
      units += kNonAsciiWidth;
    }
  }
  return units / 1000.0 * font_size * kSafety * (bold ? 1.08 : 1.0);
}

FittedText FitText(std::string_view text, double font_size, double max_width, bool bold,
                   double min_font_size) {
  const double width = TextWidth(text, font_size, bold);
  if (width <= max_width) return {std::string(text), font_size};
  const double shrunk = std::max(min_font_size, font_size * max_width / width);
  if (TextWidth(text, shrunk, bold) <= max_width) return {std::string(text), shrunk};
  constexpr std::string_view kEllipsis = "\u2026";
  std::string cut(text);
  while (!cut.empty() &&
         TextWidth(std::string(cut) + std::string(kEllipsis), shrunk, bold) > max_width) {
    // Drop the last UTF-8 code point: its continuation bytes, then its lead byte.
    while (!cut.empty() && (static_cast<unsigned char>(cut.back()) & 0xC0) == 0x80) cut.pop_back();
    if (!cut.empty()) cut.pop_back();
  }
  while (!cut.empty() && cut.back() == ' ') cut.pop_back();
  cut += kEllipsis;
  return {cut, shrunk};
}

void AppendText(std::string& out, double x, double y, std::string_view text, double font_size,
                Anchor anchor, std::string_view attributes) {
  static constexpr std::array<std::string_view, 3> kAnchors = {"start", "middle", "end"};
  out += "<text x=\"" + Num(x) + "\" y=\"" + Num(y) + "\" font-size=\"" + Num(font_size) + "\"";
  if (anchor != Anchor::kStart) {
    out += " text-anchor=\"";
    out += kAnchors[static_cast<int>(anchor)];
    out += "\"";
  }
  if (!attributes.empty()) {
    out += ' ';
    out += attributes;
  }
  out += '>' + Escape(text) + "</text>\n";
}

void AppendVerticalText(std::string& out, double x, double y, std::string_view text,
                        double font_size, std::string_view attributes) {
  std::string attrs = "transform=\"rotate(-90 " + Num(x) + " " + Num(y) + ")\"";
  if (!attributes.empty()) attrs += ' ' + std::string(attributes);
  AppendText(out, x, y, text, font_size, Anchor::kMiddle, attrs);
}

std::string DocumentStart(int width, int height) {
  const std::string w = std::to_string(width);
  const std::string h = std::to_string(height);
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + w + "\" height=\"" + h +
         "\" viewBox=\"0 0 " + w + " " + h + "\" font-family=\"" + Escape(kFontFamily) +
         "\" fill=\"#222\">\n<rect width=\"" + w + "\" height=\"" + h + "\" fill=\"#fff\"/>\n";
}

void ResolveIds(std::string& document) {
  std::uint64_t hash = 1469598103934665603ULL;  // FNV-1a
  for (const char c : document) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  char id[24];
  std::snprintf(id, sizeof(id), "u%016llx", static_cast<unsigned long long>(hash));
  for (std::size_t pos = document.find(kIdPlaceholder); pos != std::string::npos;
       pos = document.find(kIdPlaceholder, pos)) {
    document.replace(pos, kIdPlaceholder.size(), id);
  }
}

std::string WithUnit(std::string_view label, std::string_view unit) {
  std::string s(label);
  if (!unit.empty()) s += (s.empty() ? "[" : " [") + std::string(unit) + "]";
  return s;
}

}  // namespace usvid::svg
