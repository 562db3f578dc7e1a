// A method's options, declared once (docs/options.md): each with its key, type, allowed values,
// default (or none: the method decides, and its help says how) and one line of help. From that
// one declaration come the command line's flags (max_depth is --max-depth), the checks of a
// suite's method entry and of Python's keyword options, the echo of the options used in
// model.json ("options"), and the reference page docs/options.md (`usvid methods
// --markdown`). Ceres's Solver::Options::IsValid and PySINDy's per-component constructor
// arguments are the models: every value is checked where it is read in, before any fit, and
// the error names the method, the key and what is allowed.
#pragma once

#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace usvid {

// A range's open end.
inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

enum class OptionType {
  kInteger,  // a whole number in [min, max]
  kNumber,   // a finite number in [min, max] (an end open when min_ or max_exclusive)
  kChoice,   // one of `choices`
  kText,     // a string, which the method checks (a derivative method's spec)
  kList,     // names: a JSON array, or a comma-separated string; each among `choices` if any
  kFlag,     // true or false
};

struct OptionSpec {
  std::string key;  // snake_case, the same in suites, Python, model.json and C++
  OptionType type = OptionType::kNumber;
  std::string help;              // one line
  nlohmann::json default_value;  // null: none (the method decides; `help` says how)
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false, max_exclusive = false;
  std::vector<std::string> choices;   // kChoice: the values; kList: the names allowed (empty: any)
  std::vector<std::string> old_keys;  // earlier spellings a suite may still use (deprecated)

  std::string Flag() const;           // "--max-depth"
  std::string AllowedValues() const;  // "a whole number from 2 to 17", "one of r2, mse"
  std::string DefaultText() const;    // "50", "none", "+,-,*"
};

// Declarations, as a method's list writes them.
OptionSpec IntegerOption(std::string key, std::optional<long> default_value, double min, double max,
                         std::string help);
OptionSpec NumberOption(std::string key, std::optional<double> default_value, double min,
                        double max, std::string help, bool min_exclusive = false,
                        bool max_exclusive = false);
OptionSpec ChoiceOption(std::string key, std::string default_value,
                        std::vector<std::string> choices, std::string help);
OptionSpec ListOption(std::string key, std::vector<std::string> default_value,
                      std::vector<std::string> choices, std::string help);
OptionSpec FlagOption(std::string key, std::string help);
OptionSpec TextOption(std::string key, std::optional<std::string> default_value, std::string help);

// The options a method runs with: every declared key, as given or its default (a key without
// default and not given is absent). Reading a key the method did not declare is a programming
// error (std::logic_error); Unread() lists the declared keys nothing has read, which Identify
// checks after every fit so that no declared option is silently ignored.
class MethodOptions {
 public:
  MethodOptions() = default;
  MethodOptions(std::string method, const std::vector<OptionSpec>* specs, nlohmann::json values,
                std::set<std::string> given);

  bool Has(std::string_view key) const;    // a value, given or default
  bool Given(std::string_view key) const;  // given by the user (a preset may fill the others)
  long Integer(std::string_view key) const;
  double Number(std::string_view key) const;
  std::string Text(std::string_view key) const;  // a choice
  std::vector<std::string> List(std::string_view key) const;
  bool Flag(std::string_view key) const;
  std::optional<long> OptionalInteger(std::string_view key) const;
  std::optional<double> OptionalNumber(std::string_view key) const;

  // key -> value of every option with a value: model.json's "options".
  const nlohmann::json& Json() const { return values_; }
  std::vector<std::string> Unread() const;

 private:
  const nlohmann::json& Value(std::string_view key) const;

  std::string method_;
  const std::vector<OptionSpec>* specs_ = nullptr;
  nlohmann::json values_ = nlohmann::json::object();
  std::set<std::string> given_;
  mutable std::set<std::string, std::less<>> read_;
};

// `given` (key -> JSON value) checked against `specs`, for method `method`. Throws InputError,
// one line "<where>: method M: option 'K' ...: allowed: ...", for a key M does not declare
// (naming its options), a value of the wrong type or out of range. An old key is taken as its
// new one, with a note to `deprecations` (may be null).
MethodOptions ValidateOptions(const std::string& method, const std::vector<OptionSpec>& specs,
                              const nlohmann::json& given, const std::string& where,
                              std::vector<std::string>* deprecations = nullptr);

// A command-line string read as the option's type (a list: comma-separated; a flag: given).
// Throws InputError naming the flag and what is allowed.
nlohmann::json OptionFromText(const std::string& method, const OptionSpec& spec,
                              const std::string& text);

}  // namespace usvid
