// How one series of a LinePlot is drawn: a line (solid, dashed or dotted), markers, or both,
// in a palette colour unless one is given. Header only; nothing here throws.
#pragma once

#include <string>
#include <string_view>

namespace usvid {

enum class Dash { kSolid, kDashed, kDotted };

struct SeriesStyle {
  bool line = true;
  bool markers = false;
  Dash dash = Dash::kSolid;
  std::string color;           // any SVG colour ("#555", "gray"); empty = next palette colour
  double line_width = 1.5;     // [px]
  double marker_radius = 2.5;  // [px]

  static SeriesStyle Solid() { return {}; }
  // Measured data: a grey line a little wider than the models', outside the palette, so that
  // no model's colour can be taken for the data however many series follow (the palette's
  // first colour came round again at the eighth series: SINDy's line in the KVLCC2 study).
  static SeriesStyle Measured() {
    SeriesStyle s;
    s.color = "#7f7f7f";
    s.line_width = 2.0;
    return s;
  }
  static SeriesStyle Dashed() {
    SeriesStyle s;
    s.dash = Dash::kDashed;
    return s;
  }
  static SeriesStyle Dotted() {
    SeriesStyle s;
    s.dash = Dash::kDotted;
    return s;
  }
  static SeriesStyle Markers() {
    SeriesStyle s;
    s.line = false;
    s.markers = true;
    return s;
  }
  static SeriesStyle LineAndMarkers() {
    SeriesStyle s;
    s.markers = true;
    return s;
  }
};

// The stroke-dasharray attribute (with a leading space) for a dash style, "" when solid.
inline std::string_view DashAttribute(Dash dash) {
  switch (dash) {
    case Dash::kDashed:
      return " stroke-dasharray=\"7 4\"";
    case Dash::kDotted:
      return " stroke-dasharray=\"1.5 3\" stroke-linecap=\"round\"";
    case Dash::kSolid:
      break;
  }
  return "";
}

}  // namespace usvid
