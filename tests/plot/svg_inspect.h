// Helpers for the plot tests on top of xml_check.h: the polylines of an SVG path, the elements
// of one series, the texts of a group, numeric attributes, and InputError messages.
#pragma once

#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "tests/plot/xml_check.h"

namespace usvid::svg_inspect {

using Point = std::pair<double, double>;

// "M x,y L x,y ... M x,y ..." -> one point list per M.
inline std::vector<std::vector<Point>> PathPolylines(const std::string& d) {
  std::vector<std::vector<Point>> lines;
  const char* p = d.c_str();
  while (*p != '\0') {
    if (*p == 'M' || *p == 'L') {
      if (*p == 'M') lines.emplace_back();
      char* end = nullptr;
      const double x = std::strtod(p + 1, &end);
      const double y = std::strtod(end + 1, &end);  // skips the comma
      lines.back().push_back({x, y});
      p = end;
    } else {
      ++p;
    }
  }
  return lines;
}

inline bool IsSeries(const xml_check::Element& e, const std::string& name) {
  return e.name == "g" && e.Attr("class") == "series" && e.Attr("data-name") == name;
}

// The elements `tag` drawn for the series `name`.
inline std::vector<const xml_check::Element*> SeriesElements(const xml_check::Document& doc,
                                                             const std::string& name,
                                                             const std::string& tag) {
  return doc.Within(tag, [&](const xml_check::Element& e) { return IsSeries(e, name); });
}

// The elements `tag` inside groups of class `cls`.
inline std::vector<const xml_check::Element*> InClass(const xml_check::Document& doc,
                                                      const std::string& tag,
                                                      const std::string& cls) {
  return doc.Within(tag, [&](const xml_check::Element& e) { return e.Attr("class") == cls; });
}

// The texts inside groups of class `cls`.
inline std::vector<std::string> TextsOfClass(const xml_check::Document& doc,
                                             const std::string& cls) {
  std::vector<std::string> out;
  for (const auto* t : InClass(doc, "text", cls)) out.push_back(t->text);
  return out;
}

// The message of the InputError that f() throws, or "(no InputError)".
template <typename F>
std::string InputErrorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

inline double Num(const xml_check::Element& e, const std::string& attribute) {
  return std::strtod(e.Attr(attribute).c_str(), nullptr);
}

}  // namespace usvid::svg_inspect
