// Records joined for one fit (core/records.h) and the stretches between gaps
// (core/stretches.h): each record's time follows the one before after kRecordGapS, every
// record's rows are kept in order, the channels only some records have are left out and named,
// the join is a gap that cuts the joined series into exactly its records, and a split of each
// record puts every record in both parts.
#include "core/records.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/stretches.h"

namespace usvid {
namespace {

// `rows` samples at `dt` from `t0`, a channel x = offset + k and, when `with_y`, y = -k.
Dataset Record(double t0, double dt, int rows, double offset, bool with_y, std::string source) {
  Eigen::VectorXd t(rows), x(rows), y(rows);
  for (int k = 0; k < rows; ++k) {
    t(k) = t0 + k * dt;
    x(k) = offset + k;
    y(k) = -k;
  }
  Dataset d(t);
  d.Set("x", x);
  if (with_y) d.Set("y", y);
  d.metadata()["source"] = std::move(source);
  return d;
}

TEST(RecordsTest, JoinsRecordsInOrderWithAGapBetweenThem) {
  // The second record's time starts at 1894 s, as a log continuing a session does.
  std::vector<std::string> dropped;
  const Dataset joined = JoinRecords(
      {Record(0.0, 0.1, 30, 0.0, true, "a.csv"), Record(1894.0, 0.1, 20, 100.0, false, "b.csv")},
      &dropped);
  ASSERT_EQ(joined.rows(), 50);
  EXPECT_DOUBLE_EQ(joined.t()(29), 2.9);
  EXPECT_DOUBLE_EQ(joined.t()(30), 2.9 + kRecordGapS);      // the second starts after the gap
  EXPECT_NEAR(joined.t()(49) - joined.t()(30), 1.9, 1e-9);  // and keeps its own intervals
  EXPECT_EQ(joined["x"](29), 29.0);
  EXPECT_EQ(joined["x"](30), 100.0);
  EXPECT_FALSE(joined.Has("y"));  // only the first record has it
  EXPECT_EQ(dropped, std::vector<std::string>{"y"});
  EXPECT_EQ(joined.metadata().at("records"), "2");
  EXPECT_EQ(joined.Source(), "a.csv, b.csv");
}

TEST(RecordsTest, OneRecordIsReturnedAsItIsAndNoneIsAnError) {
  const Dataset one = JoinRecords({Record(5.0, 0.1, 12, 0.0, true, "a.csv")});
  EXPECT_EQ(one.t()(0), 5.0);
  EXPECT_TRUE(one.Has("y"));
  EXPECT_FALSE(one.metadata().contains("records"));
  EXPECT_THROW(JoinRecords({}), InputError);
}

// A record's maneuver (its F.record.json, docs/data.md) is the record's: one record keeps it, a
// joined one is no one maneuver and has none.
TEST(RecordsTest, OnlyALoneRecordKeepsItsManeuver) {
  Dataset a = Record(0.0, 0.1, 12, 0.0, false, "a.csv");
  a.metadata()["maneuver"] = "Z20/10";
  EXPECT_EQ(JoinRecords({a}).metadata().at("maneuver"), "Z20/10");
  const Dataset joined = JoinRecords({a, a});
  EXPECT_FALSE(joined.metadata().contains("maneuver"));
}

TEST(RecordsTest, TheJoinIsAGapThatCutsTheSeriesIntoItsRecords) {
  const Dataset joined =
      JoinRecords({Record(0.0, 0.1, 30, 0.0, false, "a"), Record(0.0, 0.1, 20, 0.0, false, "b"),
                   Record(0.0, 0.1, 25, 0.0, false, "c")});
  for (const double factor : {kGridGapFactor, kRawGapFactor}) {
    const std::vector<Stretch> s = Stretches(joined.t(), factor);
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s[0].first, 0);
    EXPECT_EQ(s[0].end, 30);
    EXPECT_EQ(s[1].first, 30);
    EXPECT_EQ(s[1].rows(), 20);
    EXPECT_EQ(s[2].end, 75);
  }
}

TEST(RecordsTest, EachRecordIsSplitSoThatEveryRecordIsInBothParts) {
  // A fit on the first parts judged on the last parts sees every maneuver in both: split at the
  // share of the joined rows, the first part would be records a and b, the last record c alone.
  const Dataset joined =
      JoinRecords({Record(0.0, 0.1, 30, 0.0, false, "a"), Record(0.0, 0.1, 60, 100.0, false, "b"),
                   Record(0.0, 0.1, 90, 200.0, false, "c")});
  const RecordSplit parts = SplitEachRecord(joined, 1.0 / 3.0, 5, "test");
  ASSERT_EQ(parts.first.rows(), 20 + 40 + 60);
  ASSERT_EQ(parts.last.rows(), 10 + 20 + 30);
  EXPECT_EQ(RecordStarts(parts.first.t()), (std::vector<long>{0, 20, 60}));
  EXPECT_EQ(RecordStarts(parts.last.t()), (std::vector<long>{0, 10, 30}));
  EXPECT_EQ(parts.first["x"](19), 19.0);  // a's first two thirds
  EXPECT_EQ(parts.last["x"](0), 20.0);    // a's last third
  EXPECT_EQ(parts.last["x"](10), 140.0);  // b's from its row 40
  EXPECT_EQ(parts.last["x"](59), 289.0);  // c's last row
  EXPECT_EQ(parts.first.metadata().at("records"), "3");
  // One record: its first rows and its last.
  const RecordSplit one = SplitEachRecord(Record(5.0, 0.1, 30, 0.0, false, "a"), 0.5, 5, "test");
  EXPECT_EQ(one.first.rows(), 15);
  EXPECT_EQ(one.last.t()(0), 6.5);
  // A record too short to give each part min_rows is an input error naming it.
  try {
    SplitEachRecord(joined, 1.0 / 3.0, 11, "hybrid");
    FAIL() << "record a has 10 rows to hold out";
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("hybrid: too few rows to hold out a part of record 1 of 3"),
        std::string::npos)
        << e.what();
  }
}

TEST(StretchesTest, ADropoutInsideARecordIsAGapAndJitterIsNot) {
  // 10 Hz with +-20 % jitter, then 0.5 s without a sample, then 10 Hz again.
  std::vector<double> times;
  for (int k = 0; k < 40; ++k) times.push_back(0.1 * k + (k % 2 ? 0.02 : -0.02));
  for (int k = 0; k < 40; ++k) times.push_back(4.4 + 0.1 * k);
  const Eigen::VectorXd t = Eigen::Map<Eigen::VectorXd>(times.data(), 80);
  const std::vector<Stretch> raw = Stretches(t, kRawGapFactor);
  ASSERT_EQ(raw.size(), 2u);
  EXPECT_EQ(raw[1].first, 40);
  EXPECT_EQ(Stretches(t.head(40), kRawGapFactor).size(), 1u);
  EXPECT_TRUE(Stretches(Eigen::VectorXd(), kRawGapFactor).empty());
}

TEST(RecordsTest, ListsOfFilesSplitAtCommasAndRejectEmptyNames) {
  EXPECT_EQ(RecordList("a.csv,b.csv", "--data"), (std::vector<std::string>{"a.csv", "b.csv"}));
  EXPECT_EQ(RecordList("a.csv", "--data"), std::vector<std::string>{"a.csv"});
  EXPECT_THROW(RecordList("", "--data"), InputError);
  EXPECT_THROW(RecordList("a.csv,", "--data"), InputError);
  EXPECT_THROW(RecordList("a.csv,,b.csv", "--data"), InputError);
}

}  // namespace
}  // namespace usvid
