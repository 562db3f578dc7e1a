#include "core/yaml_section.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "core/parse_number.h"

namespace usvid {

namespace {

template <typename Load>
YAML::Node Loaded(const std::string& label, Load load) {
  try {
    return load();
  } catch (const YAML::ParserException& e) {
    throw InputError(Located(label, e.mark.line + 1, e.mark.column + 1, e.msg));
  } catch (const YAML::Exception& e) {
    throw InputError(label + ": " + e.what());
  }
}

}  // namespace

YAML::Node LoadYamlFile(const std::string& path, const std::string& kind) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path + ": no such " + kind);
  return Loaded(path, [&] { return YAML::LoadFile(path); });
}

YAML::Node LoadYamlText(const std::string& text, const std::string& label) {
  return Loaded(label, [&] { return YAML::Load(text); });
}

YamlSection::YamlSection(std::string file, const YAML::Node& node, std::string path)
    : file_(std::move(file)), node_(node), path_(std::move(path)) {
  if (!node_.IsMap()) {
    const YAML::Mark m = node_.Mark();
    throw InputError(
        Located(file_, m.is_null() ? 0 : m.line + 1, 0,
                (path_.empty() ? std::string("the file") : path_.substr(0, path_.size() - 1)) +
                    ": expected a mapping of key: value"));
  }
}

void YamlSection::Fail(const YAML::Node& at, const std::string& what) const {
  const YAML::Mark m = at.Mark();
  throw InputError(
      Located(file_, m.is_null() ? 0 : m.line + 1, m.is_null() ? 0 : m.column + 1, path_ + what));
}

void YamlSection::FailKey(const std::string& key, const std::string& what) const {
  Fail(Has(key) ? node_[key] : node_, key + ": " + what);
}

void YamlSection::FailHere(const std::string& what) const { Fail(node_, what); }

std::optional<double> YamlSection::Number(const std::string& key) {
  Ask(key);
  const YAML::Node v = node_[key];
  if (!v.IsDefined()) return std::nullopt;
  double x = 0.0;
  if (!v.IsScalar() || !YAML::convert<double>::decode(v, x) || !std::isfinite(x))
    Fail(v, key + ": '" + (v.IsScalar() ? v.Scalar() : std::string("(not a number)")) +
                "' is not a finite number");
  return x;
}

double YamlSection::Required(const std::string& key, const std::string& what) {
  const std::optional<double> x = Number(key);
  if (!x) FailHere(key + ": missing (" + what + ")");
  return *x;
}

double YamlSection::Positive(const std::string& key, const std::string& what) {
  const double x = Required(key, what);
  if (x <= 0) FailKey(key, "must be above 0, got " + FormatNumber(x));
  return x;
}

std::optional<std::string> YamlSection::Text(const std::string& key) {
  Ask(key);
  const YAML::Node v = node_[key];
  if (!v.IsDefined()) return std::nullopt;
  if (!v.IsScalar()) Fail(v, key + ": expected a text");
  return v.Scalar();
}

std::optional<YamlSection> YamlSection::Child(const std::string& key) {
  Ask(key);
  if (!Has(key)) return std::nullopt;
  return YamlSection(file_, node_[key], path_ + key + ".");
}

YamlSection YamlSection::RequiredChild(const std::string& key, const std::string& what) {
  std::optional<YamlSection> s = Child(key);
  if (!s) FailHere(key + ": missing (" + what + ")");
  return *s;
}

YAML::Node YamlSection::Node(const std::string& key) {
  Ask(key);
  return node_[key];
}

std::vector<std::pair<std::string, YAML::Node>> YamlSection::Items() const {
  std::vector<std::pair<std::string, YAML::Node>> out;
  for (const auto& kv : node_) out.emplace_back(kv.first.Scalar(), kv.second);
  return out;
}

void YamlSection::Ask(const std::string& key) {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.push_back(key);
}

void YamlSection::RefuseUnknown() const {
  for (const auto& kv : node_) {
    if (std::find(known_.begin(), known_.end(), kv.first.Scalar()) != known_.end()) continue;
    std::string list;
    for (const std::string& key : known_) list += (list.empty() ? "" : ", ") + key;
    Fail(kv.first, kv.first.Scalar() + ": unknown key (known: " + list + ")");
  }
}

}  // namespace usvid
