// docs/data.md#data-files: what a data file may hold, and the exact place named when it may not.
#include "core/csv_dataset.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;

struct MalformedCase {
  const char* name;
  std::string text;
  const char* location;  // "file:line:column" prefix the message must start with
  const char* what;      // a phrase the message must hold
};

class MalformedCsvTest : public ::testing::TestWithParam<MalformedCase> {};

// Each kind of bad input is refused with file:line:column and what was wrong.
TEST_P(MalformedCsvTest, IsRefusedWithItsLocation) {
  const MalformedCase& c = GetParam();
  try {
    ParseDatasetCsv(c.text, "f.csv");
    FAIL() << "accepted: " << c.name;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(c.location, 0), 0u) << message;
    EXPECT_THAT(message, HasSubstr(c.what));
  }
}

INSTANTIATE_TEST_SUITE_P(
    ContractSection1, MalformedCsvTest,
    ::testing::Values(
        MalformedCase{"Empty", "", "f.csv: ", "empty"},
        MalformedCase{"BlankLinesOnly", "\n \n", "f.csv: ", "no text"},
        MalformedCase{"HeaderOnly", "t,x\n", "f.csv:1: ", "header only"},
        MalformedCase{"NoTimeColumn", "time,x\n0,1\n", "f.csv:1:1: ", "no column 't'"},
        MalformedCase{"TextInCell", "t,x\n0,1\n1,abc\n", "f.csv:3:3: ", "'abc' is not a number"},
        MalformedCase{"NanInCell", "t,x\n0,nan\n", "f.csv:2:3: ", "not a finite number"},
        MalformedCase{"InfInCell", "t,x\n0,-inf\n", "f.csv:2:3: ", "not a finite number"},
        MalformedCase{"DecreasingTime", "t,x\n0,1\n2,1\n1,1\n", "f.csv:4:1: ", "goes back"},
        MalformedCase{"RepeatedTime", "t,x\n0,1\n0,2\n", "f.csv:3:1: ", "repeats"},
        MalformedCase{"EmptyTimeCell", "t,x\n0,1\n,2\n", "f.csv:3:1: ", "empty cell"},
        MalformedCase{"ShortRow", "t,x,y\n0,1,2\n1,2\n", "f.csv:3:4: ", "short row: 2 cells"},
        MalformedCase{"LongRow", "t,x\n0,1,2\n", "f.csv:2:5: ", "long row: 3 cells"},
        MalformedCase{"SemicolonSeparator", "t;x\n0;1\n", "f.csv:1:2: ", "wrong separator"},
        MalformedCase{"TabSeparator", "t\tx\n0\t1\n", "f.csv:1:2: ", "wrong separator"},
        MalformedCase{"DecimalComma", "t,x\n0,\"1,5\"\n", "f.csv:2:3: ", "not a number"},
        MalformedCase{"BinaryBytes", std::string("t,x\n0,1\n1,\x01\x02\xff\n", 13),
                      "f.csv:3:3: ", "binary byte 0x01"},
        MalformedCase{"NulByte", std::string("t,x\n0,1\0\n", 9), "f.csv:2:4: ", "binary byte 0x00"},
        MalformedCase{"InvalidUtf8", "t,x\xff\n0,1\n", "f.csv:1:4: ", "not valid UTF-8"},
        MalformedCase{"OutOfDoubleRange", "t,x\n0,1e999\n", "f.csv:2:3: ", "out of the range"},
        MalformedCase{"DuplicateColumn", "t,x,x\n0,1,2\n", "f.csv:1:5: ", "appears twice"},
        MalformedCase{"EmptyColumnName", "t,,x\n0,1,2\n", "f.csv:1:3: ", "empty column name"},
        MalformedCase{"UnterminatedQuote", "t,\"x\n0,1\n", "f.csv:1:3: ", "unterminated"}),
    [](const auto& info) { return std::string(info.param.name); });

class CsvDatasetTest : public ::testing::Test {};

// Windows line ends and a UTF-8 byte-order mark are ordinary text.
TEST_F(CsvDatasetTest, AcceptsCrlfAndByteOrderMark) {
  const Dataset d = ParseDatasetCsv("\xEF\xBB\xBFt,u\r\n0,1.5\r\n0.1,2\r\n", "f.csv");
  ASSERT_EQ(d.rows(), 2);
  EXPECT_DOUBLE_EQ(d["u"](1), 2.0);
  EXPECT_TRUE(d.Has("u"));
}

// Extra columns are kept (and ignored by whoever does not need them); t need not come first.
TEST_F(CsvDatasetTest, KeepsExtraColumnsInAnyOrder) {
  const Dataset d = ParseDatasetCsv("u,t,comment_code\n1,0,7\n2,1,8\n", "f.csv");
  EXPECT_EQ(d.channels().size(), 2u);
  EXPECT_DOUBLE_EQ(d["comment_code"](1), 8.0);
  EXPECT_DOUBLE_EQ(d.t()(1), 1.0);
}

// Multi-rate logs: an empty cell is a sample not taken, recorded in the channel's mask.
TEST_F(CsvDatasetTest, EmptyCellsAreUnsampled) {
  const Dataset d = ParseDatasetCsv("t,imu,gps\n0,1,5\n0.02,2,\n0.04,3,\n0.06,4,6\n", "f.csv");
  const Channel& gps = d.Get("gps");
  EXPECT_TRUE(d.Get("imu").FullySampled());
  EXPECT_FALSE(gps.FullySampled());
  EXPECT_EQ(gps.sampled.count(), 2);
  EXPECT_TRUE(std::isnan(gps.values(1)));
  EXPECT_DOUBLE_EQ(gps.values(3), 6.0);
}

// Quoted names, blanks around numbers, a leading '+', no final line end: all valid.
TEST_F(CsvDatasetTest, AcceptsQuotesBlanksAndMissingFinalNewline) {
  const Dataset d = ParseDatasetCsv("\"t\",\"u\"\n 0 , +1e-3\n1,-2.5E+1", "f.csv");
  EXPECT_DOUBLE_EQ(d["u"](0), 1e-3);
  EXPECT_DOUBLE_EQ(d["u"](1), -25.0);
}

// Writing then reading gives back the same doubles, bit for bit, and the same masks.
TEST_F(CsvDatasetTest, RoundTripIsExact) {
  Eigen::VectorXd t(3);
  t << 0.0, 0.1, 0.30000000000000004;
  Dataset d(t);
  Eigen::VectorXd x(3);
  x << 1.0 / 3.0, -2e-300, 6.02214076e23;
  Eigen::Array<bool, Eigen::Dynamic, 1> s(3);
  s << true, false, true;
  d.Set("x", x, s);
  const Dataset back = ParseDatasetCsv(FormatDatasetCsv(d), "round.csv");
  EXPECT_EQ(back.t(), d.t());
  EXPECT_EQ(back.Get("x").sampled.matrix(), s.matrix());
  EXPECT_EQ(back["x"](0), x(0));
  EXPECT_EQ(back["x"](2), x(2));
}

}  // namespace
}  // namespace usvid
