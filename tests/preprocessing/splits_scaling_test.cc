// Splits never leak (contiguous blocks, k folds over blocks), and z-scores undo exactly.
#include <gtest/gtest.h>

#include "core/error.h"
#include "preprocessing/scaling.h"
#include "preprocessing/splits.h"

namespace usvid {
namespace {

class SplitsScalingTest : public ::testing::Test {};

// k folds cover every row exactly once as held-out, each held-out block is contiguous, and no
// fold trains on its own held-out rows.
TEST_F(SplitsScalingTest, BlockFoldsPartitionTheRows) {
  const auto folds = BlockFolds(1003, 4);
  ASSERT_EQ(folds.size(), 4u);
  std::vector<int> held(1003, 0);
  for (const Fold& f : folds) {
    ASSERT_EQ(f.held_out.size(), 1u);
    const RowRange h = f.held_out.front();
    for (Eigen::Index i = h.first; i < h.second; ++i) ++held[i];
    for (const RowRange& r : f.train) EXPECT_TRUE(r.second <= h.first || r.first >= h.second);
  }
  for (int h : held) EXPECT_EQ(h, 1);
  EXPECT_THROW(BlockFolds(10, 1), InputError);
}

// Over several records, every fold holds out one block of each record (a share of every
// maneuver), the held-out and training rows of a fold are disjoint and cover all rows, and a
// record shorter than k rows always trains.
TEST_F(SplitsScalingTest, FoldsOverRecordsHoldOutAShareOfEach) {
  const std::vector<RowRange> records{{0, 100}, {100, 103}, {103, 403}};
  const auto folds = BlockFolds(records, 5);
  ASSERT_EQ(folds.size(), 5u);
  std::vector<int> held(403, 0);
  for (const Fold& f : folds) {
    ASSERT_EQ(f.held_out.size(), 2u);
    EXPECT_EQ(f.held_out[0].second - f.held_out[0].first, 20);
    EXPECT_EQ(f.held_out[1].second - f.held_out[1].first, 60);
    std::vector<int> seen(403, 0);
    for (const auto& ranges : {f.held_out, f.train})
      for (const auto& [a, b] : ranges)
        for (Eigen::Index i = a; i < b; ++i) ++seen[i];
    for (int s : seen) EXPECT_EQ(s, 1);
    for (const auto& [a, b] : f.held_out)
      for (Eigen::Index i = a; i < b; ++i) ++held[i];
  }
  for (Eigen::Index i = 0; i < 403; ++i) EXPECT_EQ(held[i], i >= 100 && i < 103 ? 0 : 1) << i;
}

// Z-scores fitted on training data: mean 0 and sd 1 there; Undo gives the data back.
TEST_F(SplitsScalingTest, ZScoreRoundTrips) {
  Dataset d(Eigen::VectorXd::LinSpaced(100, 0.0, 9.9));
  d.Set("u", (d.t().array() * 3.0 + 5.0).matrix());
  d.Set("c", Eigen::VectorXd::Constant(100, 2.0));
  const ZScore z = ZScore::Fit(d, {"u", "c"});
  const Dataset s = z.Apply(d);
  EXPECT_NEAR(s["u"].mean(), 0.0, 1e-12);
  EXPECT_NEAR(std::sqrt((s["u"].array() - s["u"].mean()).square().sum() / 99.0), 1.0, 1e-12);
  EXPECT_EQ(z.Sd("c"), 1.0);
  EXPECT_LT((z.Undo(s)["u"] - d["u"]).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(ZScore::FromJson(z.ToJson()).Mean("u"), z.Mean("u"));
  const auto [train, test] = SplitAt(d, 0.7);
  EXPECT_EQ(train.rows(), 70);
  EXPECT_EQ(test.t()(0), d.t()(70));
}

}  // namespace
}  // namespace usvid
