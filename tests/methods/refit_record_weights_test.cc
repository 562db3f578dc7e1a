// Record weights (methods/refit/record_weights.h): in a refit of several records at once each
// record weighs the same in all, whatever its length, and the weights average 1; a log's own
// gaps (GPS dropouts) do not make records, the joins of core/records.h do.
#include <gtest/gtest.h>

#include <numeric>

#include "core/dataset.h"
#include "core/records.h"
#include "methods/refit/record_weights.h"

namespace usvid {
namespace {

using Segments = std::vector<std::pair<Eigen::Index, Eigen::Index>>;

// A record of `rows` rows at 10 Hz, with a 2 s dropout after its third row.
Dataset Record(Eigen::Index rows) {
  Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(rows, 0.0, 0.1 * static_cast<double>(rows - 1));
  t.tail(rows - 3).array() += 2.0;
  Dataset d(t);
  d.Set("u", Eigen::VectorXd::Ones(rows));
  return d;
}

TEST(RefitRecordWeightsTest, JoinsAreRecordsAndDropoutsAreNot) {
  const Dataset joined = JoinRecords({Record(60), Record(20)});
  EXPECT_EQ(RecordStarts(joined.t()), (std::vector<long>{0, 60}));
  EXPECT_EQ(RecordStarts(Record(60).t()), (std::vector<long>{0}));
}

TEST(RefitRecordWeightsTest, EachRecordWeighsTheSameAndTheMeanIsOne) {
  // Six segments of the long record, two of the short one.
  const Segments segments = {{0, 9},   {10, 19}, {20, 29}, {30, 39},
                             {40, 49}, {50, 59}, {60, 69}, {70, 79}};
  const std::vector<double> w = RecordWeights(segments, {0, 60});
  ASSERT_EQ(w.size(), 8u);
  const double first = std::accumulate(w.begin(), w.begin() + 6, 0.0);
  const double second = std::accumulate(w.begin() + 6, w.end(), 0.0);
  EXPECT_DOUBLE_EQ(first, second);
  EXPECT_DOUBLE_EQ((first + second) / 8.0, 1.0);
  EXPECT_DOUBLE_EQ(w[0], 8.0 / 12.0);
  EXPECT_DOUBLE_EQ(w[7], 2.0);
}

TEST(RefitRecordWeightsTest, OneRecordOrARecordWithoutSegmentsLeavesEveryWeightOne) {
  const Segments segments = {{0, 9}, {10, 19}, {20, 29}};
  for (const double w : RecordWeights(segments, {0})) EXPECT_EQ(w, 1.0);
  // The second record's rows were all spread away (max_rows): one record is left.
  for (const double w : RecordWeights(segments, {0, 500})) EXPECT_EQ(w, 1.0);
}

}  // namespace
}  // namespace usvid
