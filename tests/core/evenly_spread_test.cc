// EvenlySpread (core/evenly_spread.h): the share of a long record a bounded fit uses starts at
// its first item, reaches into its last stretch, is in order without repeats, and is the whole
// record when the bound is off or not reached.
#include "core/evenly_spread.h"

#include <gtest/gtest.h>

namespace usvid {
namespace {

TEST(EvenlySpreadTest, KeepsEveryItemWhenTheBoundIsOffOrNotReached) {
  const std::vector<long> all = {0, 1, 2, 3, 4};
  EXPECT_EQ(EvenlySpread(5, 0), all);
  EXPECT_EQ(EvenlySpread(5, -1), all);
  EXPECT_EQ(EvenlySpread(5, 5), all);
  EXPECT_EQ(EvenlySpread(5, 100), all);
  EXPECT_TRUE(EvenlySpread(0, 10).empty());
}

TEST(EvenlySpreadTest, SpreadsABoundedShareOverTheWholeRange) {
  const std::vector<long> kept = EvenlySpread(1000, 7);
  ASSERT_EQ(kept.size(), 7u);
  EXPECT_EQ(kept.front(), 0);
  EXPECT_GE(kept.back() + 1000.0 / 7.0, 999.0);  // within one spacing of the last item
  for (size_t i = 1; i < kept.size(); ++i) {
    EXPECT_GT(kept[i], kept[i - 1]);
    EXPECT_NEAR(kept[i] - kept[i - 1], 1000.0 / 7.0, 1.0);  // evenly
  }
}

}  // namespace
}  // namespace usvid
