#include "core/parse_number.h"

#include <array>
#include <charconv>
#include <cmath>

namespace usvid {
namespace {

std::string_view Trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// nan, inf or infinity (any case, optionally signed; from_chars's nan(chars) too): a number that
// is not finite. Text that only starts so ("info", "nano") is not a number at all.
bool LooksNonFinite(std::string_view s) {
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) s.remove_prefix(1);
  auto is = [&](std::string_view word) {
    if (s.size() != word.size()) return false;
    for (size_t i = 0; i < s.size(); ++i)
      if (static_cast<char>(s[i] | 0x20) != word[i]) return false;
    return true;
  };
  const bool nan_chars = s.size() >= 5 && (s.substr(0, 4) == "nan(" || s.substr(0, 4) == "NAN(") &&
                         s.back() == ')';
  return is("nan") || is("inf") || is("infinity") || nan_chars;
}

}  // namespace

ParsedNumber ParseNumber(std::string_view text) {
  std::string_view s = Trim(text);
  if (s.empty()) return {NumberStatus::kEmpty, 0.0};
  if (LooksNonFinite(s)) return {NumberStatus::kNotFinite, 0.0};
  std::string_view digits = s;
  if (digits.front() == '+') {
    digits.remove_prefix(1);
    if (digits.empty() || digits.front() == '+' || digits.front() == '-')
      return {NumberStatus::kNotANumber, 0.0};
  }
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value,
                                         std::chars_format::general);
  if (ec == std::errc::result_out_of_range) {
    // from_chars also reports underflow this way; a tiny value is a zero, not bad input.
    if (end == digits.data() + digits.size()) {
      const double approx = std::strtod(std::string(digits).c_str(), nullptr);
      if (std::isfinite(approx) && std::abs(approx) < 1.0) return {NumberStatus::kOk, approx};
    }
    return {NumberStatus::kOutOfRange, 0.0};
  }
  if (ec != std::errc() || end != digits.data() + digits.size())
    return {NumberStatus::kNotANumber, 0.0};
  if (!std::isfinite(value)) return {NumberStatus::kNotFinite, 0.0};
  return {NumberStatus::kOk, value};
}

std::string DescribeNumberStatus(NumberStatus status, std::string_view text) {
  const std::string quoted = "'" + std::string(Trim(text)) + "'";
  switch (status) {
    case NumberStatus::kOk:
      return quoted + " is a number";
    case NumberStatus::kEmpty:
      return "empty cell where a number is required";
    case NumberStatus::kNotANumber:
      return quoted + " is not a number";
    case NumberStatus::kNotFinite:
      return quoted + " is not a finite number (nan and inf are not allowed)";
    case NumberStatus::kOutOfRange:
      return quoted + " is out of the range of a double";
  }
  return quoted;
}

std::string FormatNumber(double value) {
  std::array<char, 32> buf{};
  const auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), value);
  return std::string(buf.data(), ec == std::errc() ? end : buf.data());
}

}  // namespace usvid
