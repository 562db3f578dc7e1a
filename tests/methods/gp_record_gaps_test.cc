// GP's simulations never run across a gap (issue 38): on the mass-spring-damper record cut in
// two by a 1000 s gap, as records joined for one fit are, the short-horizon segments start
// afresh after it and none straddles it, and the free run of the record runs each stretch
// from its own first row, so the true model still simulates it to a small error (one RK4 step
// across the gap would leave every bound).
#include <gtest/gtest.h>

#include "methods/gp/segment_simulator.h"
#include "tests/methods/gp_msd_record.h"

namespace usvid::gp {
namespace {

using testing::Linear;

SelectionData WithGapAt(long row) {
  SelectionData d = testing::MsdRecord(6000);
  for (long k = row; k < d.t.size(); ++k) d.t(k) += 1000.0;
  return d;
}

TEST(GpRecordGapsTest, SegmentsRestartAfterAGapAndNeverStraddleIt) {
  const SelectionData d = WithGapAt(3010);
  const long steps = 200;
  const std::vector<long> starts = SegmentSimulator::Starts(d.t, 0, 6000, steps);
  bool restarted = false;
  for (const long s : starts) {
    EXPECT_TRUE(s + steps < 3010 || s >= 3010) << "a segment from row " << s;
    restarted |= s == 3010;
  }
  EXPECT_TRUE(restarted);
  // Without the gap: every `steps` rows from the first.
  const SelectionData whole = testing::MsdRecord(6000);
  EXPECT_EQ(SegmentSimulator::Starts(whole.t, 1000, 6000, steps).front(), 1000);
  EXPECT_EQ(SegmentSimulator::Starts(whole.t, 1000, 6000, steps).size(), 24u);
}

TEST(GpRecordGapsTest, TheFreeRunStartsEachStretchFromItsOwnFirstRow) {
  const SelectionData d = WithGapAt(3010);
  const SegmentSimulator sim(d, {1});
  const Model truth = Linear({{0, -0.2}, {1, -0.1}, {2, 0.1}});
  bool diverged = true;
  const double error = sim.FreeRunError({&truth}, diverged);
  EXPECT_FALSE(diverged);
  EXPECT_LT(error, 1e-3);
}

}  // namespace
}  // namespace usvid::gp
