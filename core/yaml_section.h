// A YAML mapping read key by key (yaml-cpp): every key must be known, and every error names the
// file, line and column and the key's path. The vessel files (simulation/vessel_file.h) and the
// vessel folders' track files (harness/track_file.h) are read with it.
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace usvid {

// The YAML document of `path`; InputError "path:line:column: what" on a syntax error, and
// "path: no such KIND" when there is no such file.
YAML::Node LoadYamlFile(const std::string& path, const std::string& kind);
// The YAML document `text` (an embedded file), its syntax errors named by `label`.
YAML::Node LoadYamlText(const std::string& text, const std::string& label);

class YamlSection {
 public:
  // `path` is the keys above this mapping, each followed by '.' ("" at the top). Throws when
  // `node` is no mapping.
  YamlSection(std::string file, const YAML::Node& node, std::string path);

  [[noreturn]] void Fail(const YAML::Node& at, const std::string& what) const;
  [[noreturn]] void FailKey(const std::string& key, const std::string& what) const;
  [[noreturn]] void FailHere(const std::string& what) const;

  bool Has(const std::string& key) const { return node_[key].IsDefined(); }

  std::optional<double> Number(const std::string& key);
  double Required(const std::string& key, const std::string& what);
  double Positive(const std::string& key, const std::string& what);
  std::optional<std::string> Text(const std::string& key);
  std::optional<YamlSection> Child(const std::string& key);
  YamlSection RequiredChild(const std::string& key, const std::string& what);
  // The key's node as it is (a list, say), marked known; undefined when absent.
  YAML::Node Node(const std::string& key);
  // Every key of the mapping, with its node (free-form sections: coefficients, columns).
  std::vector<std::pair<std::string, YAML::Node>> Items() const;
  // Fails on the first key that was never asked for, listing the keys that were, in the order
  // asked: each key is named once, where it is read.
  void RefuseUnknown() const;

  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

 private:
  std::string file_;
  YAML::Node node_;
  std::string path_;
  std::vector<std::string> known_;  // the keys asked for, in order, once each

  void Ask(const std::string& key);
};

}  // namespace usvid
