// docs/data.md#data-files: what a data file may hold, and the exact place named when it may not.
#include "core/csv_dataset.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <vector>

#include "core/error.h"
#include "core/parse_number.h"

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
        MalformedCase{"DecimalCommaInTime", "t,x\n\"0,5\",1\n", "f.csv:2:1: ", "not a number"},
        MalformedCase{"TextAfterNumbers", "t,x\n0,1\n1,2\n2,fast\n", "f.csv:4:3: ",
                      "column 'x': 'fast' is not a number"},
        MalformedCase{"NanInTextLookingColumn", "t,x\n0,\n1,NaN\n", "f.csv:3:3: ",
                      "not a finite number"},
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
  EXPECT_EQ(gps.SampleCount(), 2);
  EXPECT_TRUE(std::isnan(gps.Value(1)));
  EXPECT_DOUBLE_EQ(gps.Value(3), 6.0);
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
  EXPECT_EQ(back.Get("x").sampled().matrix(), s.matrix());
  EXPECT_EQ(back["x"](0), x(0));
  EXPECT_EQ(back["x"](2), x(2));
}

// A column whose first value is text (a mode, a comment) is kept aside, not refused: the other
// columns read as numbers, and only asking for it as a number throws, with where its text stood.
TEST_F(CsvDatasetTest, TextColumnIsKeptAsideAndRefusedOnlyWhenNeeded) {
  const Dataset d = ParseDatasetCsv(
      "t,u,mode,comment\n0,1,,start\n1,2,auto,x\n2,3,3,\"1,5\"\n", "f.csv");
  EXPECT_EQ(d.rows(), 3);
  EXPECT_DOUBLE_EQ(d["u"](2), 3.0);
  EXPECT_FALSE(d.Has("mode"));
  EXPECT_FALSE(d.Has("comment"));
  ASSERT_EQ(d.text_columns().size(), 2u);
  EXPECT_EQ(d.text_columns()[0].name, "mode");
  try {
    d.Get("mode");
    FAIL() << "a text column read as a number";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "f.csv:3:5: column 'mode': 'auto' is not a number");
  }
  EXPECT_THROW(d.CheckNotText("comment"), InputError);
  EXPECT_NO_THROW(d.CheckNotText("u"));
  // A window of the record keeps the note of where the text stood.
  EXPECT_THROW(d.Rows(1, 2).Get("comment"), InputError);
}

// Text that only starts like nan or inf ("info", "nano") is text, not a non-finite number.
TEST_F(CsvDatasetTest, WordsStartingLikeNanOrInfAreText) {
  EXPECT_EQ(ParseNumber("info").status, NumberStatus::kNotANumber);
  EXPECT_EQ(ParseNumber("nano").status, NumberStatus::kNotANumber);
  EXPECT_EQ(ParseNumber("-inf").status, NumberStatus::kNotFinite);
  EXPECT_EQ(ParseNumber("nan(0x1)").status, NumberStatus::kNotFinite);
  const Dataset d = ParseDatasetCsv("t,note\n0,info\n1,nano\n", "f.csv");
  EXPECT_EQ(d.text_columns().size(), 1u);
}

class CsvFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("usvid_csv_file_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& text) {
    const auto path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }
  std::filesystem::path dir_;
};

// The file is streamed, not read whole, and gives what parsing the same text gives: values,
// masks, text columns and the located errors, with CRLF, a byte-order mark and blank lines.
TEST_F(CsvFileTest, StreamedFileReadsAsItsText) {
  const std::string text =
      "\xEF\xBB\xBFt,u,gps,mode\r\n0,1.5,7,a\r\n\r\n0.5,-2,,b\r\n1,3e2,8,c";
  const std::string path = Write("good.csv", text);
  const Dataset file = ReadDatasetCsv(path);
  const Dataset parsed = ParseDatasetCsv(text, path);
  ASSERT_EQ(file.rows(), 3);
  EXPECT_EQ(file.t(), parsed.t());
  EXPECT_EQ(file["u"], parsed["u"]);
  EXPECT_EQ(file.Get("gps").sampled().matrix(), parsed.Get("gps").sampled().matrix());
  ASSERT_EQ(file.text_columns().size(), 1u);
  EXPECT_EQ(file.text_columns()[0].Error(), parsed.text_columns()[0].Error());
  for (const std::string bad : {"t,u\n0,1\n0,2\n", "t,u\n0,1\n1,2,3\n", "t,u\n0,1\n1,\x01\n"}) {
    std::string from_file, from_text;
    try {
      ReadDatasetCsv(Write("bad.csv", bad));
    } catch (const InputError& e) {
      from_file = e.what();
    }
    try {
      ParseDatasetCsv(bad, (dir_ / "bad.csv").string());
    } catch (const InputError& e) {
      from_text = e.what();
    }
    EXPECT_FALSE(from_file.empty());
    EXPECT_EQ(from_file, from_text);
  }
  EXPECT_THROW(ReadDatasetCsv(Write("empty.csv", "")), InputError);
  EXPECT_THROW(ReadDatasetCsv(dir_.string()), InputError);
}

// F.record.json beside F.csv gives the record's maneuver (docs/data.md); a malformed one is
// refused, naming it; a file without one has none.
TEST_F(CsvFileTest, RecordFileGivesTheManeuver) {
  EXPECT_EQ(RecordJsonPath("runs/zz.csv"), "runs/zz.record.json");
  EXPECT_EQ(RecordJsonPath("runs.v2/zz"), "runs.v2/zz.record.json");
  const std::string path = Write("zz.csv", "t,u\n0,1\n1,2\n");
  EXPECT_FALSE(ReadDatasetCsv(path).metadata().contains("maneuver"));
  Write("zz.record.json", R"({"maneuver": "Z20\u00b0/10\u00b0 starting to starboard",
                              "imported_from": "a.dat", "format": "hsva-dat", "scale": 1})");
  EXPECT_EQ(ReadDatasetCsv(path).metadata().at("maneuver"),
            "Z20\xC2\xB0/10\xC2\xB0 starting to starboard");
  const std::string record = (dir_ / "zz.record.json").string();
  for (const std::string bad : {"{", "[]", R"({"maneuver": 3})", R"({"maneuver": ""})", "{}"}) {
    Write("zz.record.json", bad);
    try {
      ReadDatasetCsv(path);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(record, 0), 0u) << e.what();
    }
  }
}

// A long read reports its progress, in order, ending with every row.
TEST_F(CsvFileTest, ReportsProgressInOrder) {
  std::string text = "t,u\n";
  for (int i = 0; i < 5000; ++i) text += std::to_string(i) + "," + std::to_string(i % 7) + "\n";
  std::vector<std::pair<double, Eigen::Index>> seen;
  CsvReadOptions options;
  options.progress = [&](double f, Eigen::Index rows) { seen.emplace_back(f, rows); };
  const Dataset d = ReadDatasetCsv(Write("long.csv", text), options);
  EXPECT_EQ(d.rows(), 5000);
  ASSERT_GE(seen.size(), 9u);
  ASSERT_LE(seen.size(), 11u);
  for (size_t k = 1; k < seen.size(); ++k) {
    EXPECT_GT(seen[k].first, seen[k - 1].first);
    EXPECT_GT(seen[k].second, seen[k - 1].second);
  }
  EXPECT_NEAR(seen.back().first, 1.0, 1e-9);
  EXPECT_EQ(seen.back().second, 5000);
}

}  // namespace
}  // namespace usvid
