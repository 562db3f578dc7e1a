// Numbers in data files: '.' decimal point, finite, within double range.
#include "core/parse_number.h"

#include <gtest/gtest.h>

namespace usvid {
namespace {

class ParseNumberTest : public ::testing::Test {};

// The forms a logger writes are read exactly.
TEST_F(ParseNumberTest, ReadsDecimalAndExponentForms) {
  EXPECT_EQ(ParseNumber("1.35E-01").value, 0.135);
  EXPECT_EQ(ParseNumber("-4.09E-04").value, -4.09e-4);
  EXPECT_EQ(ParseNumber("+7").value, 7.0);
  EXPECT_EQ(ParseNumber(" 2.5 ").value, 2.5);
}

// What is not a finite double is refused, each with its own reason.
TEST_F(ParseNumberTest, RefusesWhatIsNotAFiniteDouble) {
  EXPECT_EQ(ParseNumber("").status, NumberStatus::kEmpty);
  EXPECT_EQ(ParseNumber("NaN").status, NumberStatus::kNotFinite);
  EXPECT_EQ(ParseNumber("-Infinity").status, NumberStatus::kNotFinite);
  EXPECT_EQ(ParseNumber("1e999").status, NumberStatus::kOutOfRange);
  EXPECT_EQ(ParseNumber("1,5").status, NumberStatus::kNotANumber);
  EXPECT_EQ(ParseNumber("0x10").status, NumberStatus::kNotANumber);
  EXPECT_EQ(ParseNumber("++1").status, NumberStatus::kNotANumber);
  EXPECT_EQ(ParseNumber("1.2.3").status, NumberStatus::kNotANumber);
}

// A value below the smallest double is a zero, not bad input.
TEST_F(ParseNumberTest, UnderflowIsZero) {
  const ParsedNumber p = ParseNumber("1e-400");
  EXPECT_EQ(p.status, NumberStatus::kOk);
  EXPECT_EQ(p.value, 0.0);
}

// FormatNumber gives the shortest text that reads back to the same double.
TEST_F(ParseNumberTest, FormatRoundTrips) {
  for (double v : {0.1, 1.0 / 3.0, -1e-310, 123456789.125, 0.0}) {
    EXPECT_EQ(ParseNumber(FormatNumber(v)).value, v);
  }
  EXPECT_EQ(FormatNumber(0.1), "0.1");
}

}  // namespace
}  // namespace usvid
