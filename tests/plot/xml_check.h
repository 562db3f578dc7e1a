// A tiny XML reader for the plot tests: checks that a document is well formed (one root,
// balanced and matching tags, quoted attributes, only the five predefined entities or numeric
// references, no raw '<' or '&' in text) and lists its elements with attributes and unescaped
// text, so that tests can look up a path's coordinates or a label's text.
#pragma once

#include <cctype>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace usvid::xml_check {

struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;  // the element's own character data, unescaped
  int parent = -1;   // index into Document::elements, -1 for the root
  std::string Attr(const std::string& key) const {
    const auto it = attributes.find(key);
    return it == attributes.end() ? "" : it->second;
  }
};

struct Document {
  std::vector<Element> elements;  // in document order
  std::string error;              // empty when well formed
  bool Ok() const { return error.empty(); }
  // Elements named `name` that have an ancestor satisfying `pred`.
  template <typename Pred>
  std::vector<const Element*> Within(const std::string& name, Pred pred) const {
    std::vector<const Element*> out;
    for (const Element& e : elements) {
      if (e.name != name) continue;
      for (int p = e.parent; p >= 0; p = elements[p].parent) {
        if (pred(elements[p])) {
          out.push_back(&e);
          break;
        }
      }
    }
    return out;
  }
  std::vector<const Element*> Named(const std::string& name) const {
    std::vector<const Element*> out;
    for (const Element& e : elements) {
      if (e.name == name) out.push_back(&e);
    }
    return out;
  }
};

// Unescapes `s`; returns false on a malformed reference.
inline bool Unescape(std::string_view s, std::string& out) {
  static const std::map<std::string, std::string, std::less<>> kEntities = {
      {"amp", "&"}, {"lt", "<"}, {"gt", ">"}, {"quot", "\""}, {"apos", "'"}};
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '<') return false;
    if (s[i] != '&') {
      out += s[i];
      continue;
    }
    const std::size_t end = s.find(';', i);
    if (end == std::string_view::npos) return false;
    const std::string_view name = s.substr(i + 1, end - i - 1);
    if (!name.empty() && name[0] == '#') {
      if (name.size() < 2) return false;
      out += '?';  // numeric references are not used by the plots; accepted as such
    } else {
      const auto it = kEntities.find(name);
      if (it == kEntities.end()) return false;
      out += it->second;
    }
    i = end;
  }
  return true;
}

inline Document Parse(std::string_view xml) {
  Document doc;
  std::vector<int> open;
  bool root_closed = false;
  std::size_t i = 0;
  const auto fail = [&doc, &i](const std::string& what) {
    doc.error = what + " at offset " + std::to_string(i);
    return doc;
  };
  const auto is_name = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == ':' ||
           c == '.';
  };
  while (i < xml.size()) {
    if (xml[i] != '<') {
      const std::size_t next = std::min(xml.find('<', i), xml.size());
      std::string text;
      if (!Unescape(xml.substr(i, next - i), text)) return fail("bad character data");
      if (open.empty()) {
        if (text.find_first_not_of(" \t\r\n") != std::string::npos) {
          return fail("text outside the root element");
        }
      } else {
        doc.elements[open.back()].text += text;
      }
      i = next;
      continue;
    }
    if (xml.substr(i, 4) == "<!--") {
      const std::size_t end = xml.find("-->", i);
      if (end == std::string_view::npos) return fail("unterminated comment");
      i = end + 3;
      continue;
    }
    if (xml.substr(i, 2) == "</") {
      std::size_t j = i + 2;
      while (j < xml.size() && is_name(xml[j])) ++j;
      const std::string name(xml.substr(i + 2, j - i - 2));
      if (open.empty() || doc.elements[open.back()].name != name) {
        return fail("closing tag </" + name + "> does not match");
      }
      if (j >= xml.size() || xml[j] != '>') return fail("malformed closing tag");
      open.pop_back();
      root_closed = open.empty();
      i = j + 1;
      continue;
    }
    if (root_closed) return fail("second root element");
    Element e;
    std::size_t j = i + 1;
    while (j < xml.size() && is_name(xml[j])) ++j;
    e.name = std::string(xml.substr(i + 1, j - i - 1));
    if (e.name.empty()) return fail("empty tag name");
    e.parent = open.empty() ? -1 : open.back();
    bool self_closing = false;
    for (;;) {
      while (j < xml.size() && std::isspace(static_cast<unsigned char>(xml[j]))) ++j;
      if (j >= xml.size()) return fail("unterminated tag <" + e.name + ">");
      if (xml[j] == '>') break;
      if (xml.substr(j, 2) == "/>") {
        self_closing = true;
        ++j;
        break;
      }
      const std::size_t k = j;
      while (j < xml.size() && is_name(xml[j])) ++j;
      const std::string key(xml.substr(k, j - k));
      if (key.empty() || j + 1 >= xml.size() || xml[j] != '=' ||
          (xml[j + 1] != '"' && xml[j + 1] != '\'')) {
        return fail("malformed attribute in <" + e.name + ">");
      }
      const char quote = xml[j + 1];
      const std::size_t end = xml.find(quote, j + 2);
      if (end == std::string_view::npos) return fail("unterminated attribute value");
      std::string value;
      if (!Unescape(xml.substr(j + 2, end - j - 2), value)) return fail("bad attribute value");
      if (e.attributes.count(key) != 0) return fail("duplicate attribute " + key);
      e.attributes[key] = value;
      j = end + 1;
    }
    doc.elements.push_back(std::move(e));
    if (!self_closing) {
      open.push_back(static_cast<int>(doc.elements.size()) - 1);
    } else {
      root_closed = open.empty();
    }
    i = j + 1;
  }
  if (!open.empty()) return fail("unclosed <" + doc.elements[open.back()].name + ">");
  if (doc.elements.empty()) return fail("no root element");
  return doc;
}

}  // namespace usvid::xml_check
