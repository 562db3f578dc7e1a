#include "methods/method_options.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/parse_number.h"

namespace usvid {
namespace {

std::string Joined(const std::vector<std::string>& items, const char* separator = ", ") {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : separator) + s;
  return out;
}

std::vector<std::string> SplitCommas(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

bool InRange(const OptionSpec& s, double v) {
  return std::isfinite(v) && (s.min_exclusive ? v > s.min : v >= s.min) &&
         (s.max_exclusive ? v < s.max : v <= s.max);
}

// The value checked and in its stored form (a list as an array), or nullopt when not allowed.
std::optional<nlohmann::json> Checked(const OptionSpec& s, const nlohmann::json& v) {
  switch (s.type) {
    case OptionType::kInteger:
      if (!v.is_number_integer()) return std::nullopt;
      if (!v.is_number_unsigned() && v.get<int64_t>() < 0 && s.min >= 0) return std::nullopt;
      if (!InRange(s, static_cast<double>(v.get<int64_t>()))) return std::nullopt;
      return v;
    case OptionType::kNumber:
      if (!v.is_number() || !InRange(s, v.get<double>())) return std::nullopt;
      return v;
    case OptionType::kChoice:
      if (!v.is_string() || std::ranges::find(s.choices, v.get<std::string>()) == s.choices.end())
        return std::nullopt;
      return v;
    case OptionType::kText:
      if (!v.is_string()) return std::nullopt;
      return v;
    case OptionType::kList: {
      std::vector<std::string> names;
      if (v.is_string()) {
        names = SplitCommas(v.get<std::string>());
      } else if (v.is_array()) {
        for (const auto& item : v) {
          if (!item.is_string()) return std::nullopt;
          names.push_back(item.get<std::string>());
        }
      } else {
        return std::nullopt;
      }
      for (const std::string& n : names)
        if (n.empty() || (!s.choices.empty() && std::ranges::find(s.choices, n) == s.choices.end()))
          return std::nullopt;
      return nlohmann::json(names);
    }
    case OptionType::kFlag:
      if (!v.is_boolean()) return std::nullopt;
      return v;
  }
  return std::nullopt;
}

std::string KeysOf(const std::vector<OptionSpec>& specs) {
  std::vector<std::string> keys;
  for (const OptionSpec& s : specs) keys.push_back(s.key);
  return keys.empty() ? "none" : Joined(keys);
}

OptionSpec Spec(std::string key, OptionType type, nlohmann::json default_value, std::string help) {
  OptionSpec s;
  s.key = std::move(key);
  s.type = type;
  s.default_value = std::move(default_value);
  s.help = std::move(help);
  return s;
}

}  // namespace

std::string OptionSpec::Flag() const {
  std::string flag = "--" + key;
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

std::string OptionSpec::AllowedValues() const {
  auto bound = [&](double v) {  // whole bounds in full: "1000000000", not "1e+09"
    return type == OptionType::kInteger || (v == std::floor(v) && std::abs(v) < 1e15)
               ? std::to_string(static_cast<long long>(v))
               : FormatNumber(v);
  };
  const bool low = std::isfinite(min), high = std::isfinite(max);
  std::string range;
  if (low && high)
    range = (min_exclusive ? "in (" : "in [") + bound(min) + ", " + bound(max) +
            (max_exclusive ? ")" : "]");
  else if (low)
    range = (min_exclusive ? "> " : ">= ") + bound(min);
  else if (high)
    range = (max_exclusive ? "< " : "<= ") + bound(max);
  switch (type) {
    case OptionType::kInteger:
      return "a whole number" + (range.empty() ? "" : " " + range);
    case OptionType::kNumber:
      return "a finite number" + (range.empty() ? "" : " " + range);
    case OptionType::kChoice:
      return "one of " + Joined(choices);
    case OptionType::kText:
      return "a string";
    case OptionType::kList:
      return choices.empty() ? "a list of names" : "a list of " + Joined(choices);
    case OptionType::kFlag:
      return "true or false";
  }
  return "";
}

std::string OptionSpec::DefaultText() const {
  if (default_value.is_null()) return "none";
  if (default_value.is_string()) return default_value.get<std::string>();
  if (default_value.is_boolean()) return default_value.get<bool>() ? "true" : "false";
  if (default_value.is_array()) {
    std::vector<std::string> names = default_value.get<std::vector<std::string>>();
    return names.empty() ? "none" : Joined(names, ",");
  }
  return FormatNumber(default_value.get<double>());
}

OptionSpec IntegerOption(std::string key, std::optional<long> default_value, double min, double max,
                         std::string help) {
  OptionSpec s =
      Spec(std::move(key), OptionType::kInteger,
           default_value ? nlohmann::json(*default_value) : nlohmann::json(), std::move(help));
  s.min = min;
  s.max = max;
  return s;
}

OptionSpec NumberOption(std::string key, std::optional<double> default_value, double min,
                        double max, std::string help, bool min_exclusive, bool max_exclusive) {
  OptionSpec s =
      Spec(std::move(key), OptionType::kNumber,
           default_value ? nlohmann::json(*default_value) : nlohmann::json(), std::move(help));
  s.min = min;
  s.max = max;
  s.min_exclusive = min_exclusive;
  s.max_exclusive = max_exclusive;
  return s;
}

OptionSpec ChoiceOption(std::string key, std::string default_value,
                        std::vector<std::string> choices, std::string help) {
  OptionSpec s = Spec(std::move(key), OptionType::kChoice, default_value, std::move(help));
  s.choices = std::move(choices);
  return s;
}

OptionSpec ListOption(std::string key, std::vector<std::string> default_value,
                      std::vector<std::string> choices, std::string help) {
  OptionSpec s = Spec(std::move(key), OptionType::kList, default_value, std::move(help));
  s.choices = std::move(choices);
  return s;
}

OptionSpec TextOption(std::string key, std::optional<std::string> default_value, std::string help) {
  return Spec(std::move(key), OptionType::kText,
              default_value ? nlohmann::json(*default_value) : nlohmann::json(), std::move(help));
}

OptionSpec FlagOption(std::string key, std::string help) {
  return Spec(std::move(key), OptionType::kFlag, false, std::move(help));
}

MethodOptions::MethodOptions(std::string method, const std::vector<OptionSpec>* specs,
                             nlohmann::json values, std::set<std::string> given)
    : method_(std::move(method)),
      specs_(specs),
      values_(std::move(values)),
      given_(std::move(given)) {}

const nlohmann::json& MethodOptions::Value(std::string_view key) const {
  const bool declared =
      specs_ && std::ranges::any_of(*specs_, [&](const OptionSpec& s) { return s.key == key; });
  if (!declared)
    throw std::logic_error("method " + method_ + " reads option '" + std::string(key) +
                           "', which it does not declare");
  read_.insert(std::string(key));
  static const nlohmann::json kNone;
  const auto it = values_.find(key);
  return it == values_.end() ? kNone : *it;
}

bool MethodOptions::Has(std::string_view key) const { return !Value(key).is_null(); }

bool MethodOptions::Given(std::string_view key) const {
  Value(key);
  return given_.contains(std::string(key));
}

long MethodOptions::Integer(std::string_view key) const { return Value(key).get<long>(); }
double MethodOptions::Number(std::string_view key) const { return Value(key).get<double>(); }
std::string MethodOptions::Text(std::string_view key) const {
  return Value(key).get<std::string>();
}
std::vector<std::string> MethodOptions::List(std::string_view key) const {
  return Value(key).get<std::vector<std::string>>();
}
bool MethodOptions::Flag(std::string_view key) const { return Value(key).get<bool>(); }

std::optional<long> MethodOptions::OptionalInteger(std::string_view key) const {
  const nlohmann::json& v = Value(key);
  return v.is_null() ? std::nullopt : std::optional<long>(v.get<long>());
}

std::optional<double> MethodOptions::OptionalNumber(std::string_view key) const {
  const nlohmann::json& v = Value(key);
  return v.is_null() ? std::nullopt : std::optional<double>(v.get<double>());
}

std::vector<std::string> MethodOptions::Unread() const {
  std::vector<std::string> unread;
  if (specs_)
    for (const OptionSpec& s : *specs_)
      if (!read_.contains(s.key)) unread.push_back(s.key);
  return unread;
}

MethodOptions ValidateOptions(const std::string& method, const std::vector<OptionSpec>& specs,
                              const nlohmann::json& given, const std::string& where,
                              std::vector<std::string>* deprecations) {
  const std::string prefix = (where.empty() ? "" : where + ": ") + "method " + method + ": ";
  if (!given.is_null() && !given.is_object())
    throw InputError(prefix + "options must be a JSON object of key: value");
  nlohmann::json values = nlohmann::json::object();
  std::set<std::string> keys_given;
  if (given.is_object())
    for (const auto& [key, value] : given.items()) {
      const auto spec = std::ranges::find_if(specs, [&](const OptionSpec& s) {
        return s.key == key || std::ranges::find(s.old_keys, key) != s.old_keys.end();
      });
      if (spec == specs.end())
        throw InputError(prefix + "unknown option '" + key + "' (its options: " + KeysOf(specs) +
                         ")");
      if (spec->key != key && deprecations)
        deprecations->push_back(prefix + "option '" + key + "' is now '" + spec->key + "'");
      if (keys_given.contains(spec->key))
        throw InputError(prefix + "option '" + spec->key + "' given twice");
      const std::optional<nlohmann::json> v = Checked(*spec, value);
      if (!v)
        throw InputError(prefix + "option '" + spec->key + "' " + value.dump() +
                         " is not allowed: " + spec->AllowedValues());
      values[spec->key] = *v;
      keys_given.insert(spec->key);
    }
  for (const OptionSpec& s : specs)
    if (!values.contains(s.key) && !s.default_value.is_null()) values[s.key] = s.default_value;
  return MethodOptions(method, &specs, std::move(values), std::move(keys_given));
}

nlohmann::json OptionFromText(const std::string& method, const OptionSpec& spec,
                              const std::string& text) {
  auto refuse = [&]() -> nlohmann::json {
    throw InputError(spec.Flag() + " '" + text + "': method " + method +
                     ": allowed: " + spec.AllowedValues());
  };
  switch (spec.type) {
    case OptionType::kInteger: {
      const ParsedNumber n = ParseNumber(text);
      if (n.status != NumberStatus::kOk || n.value != std::floor(n.value) ||
          std::abs(n.value) > 9e15)
        return refuse();
      return nlohmann::json(static_cast<int64_t>(n.value));
    }
    case OptionType::kNumber: {
      const ParsedNumber n = ParseNumber(text);
      if (n.status != NumberStatus::kOk) return refuse();
      return nlohmann::json(n.value);
    }
    case OptionType::kChoice:
    case OptionType::kText:
      return nlohmann::json(text);
    case OptionType::kList:
      return nlohmann::json(SplitCommas(text));
    case OptionType::kFlag:
      return nlohmann::json(true);
  }
  return refuse();
}

}  // namespace usvid
