// Strict parsing of one decimal number from a text cell ('.' decimal point, optional sign and
// exponent, surrounding blanks allowed). nan, inf and values beyond double range are refused.
#pragma once

#include <string>
#include <string_view>

namespace usvid {

enum class NumberStatus { kOk, kEmpty, kNotANumber, kNotFinite, kOutOfRange };

struct ParsedNumber {
  NumberStatus status = NumberStatus::kEmpty;
  double value = 0.0;
};

ParsedNumber ParseNumber(std::string_view text);

// A one-line reason for a status other than kOk, quoting the text, e.g.
// "'abc' is not a number".
std::string DescribeNumberStatus(NumberStatus status, std::string_view text);

// Shortest decimal text that reads back to exactly the same double.
std::string FormatNumber(double value);

}  // namespace usvid
