// GP's segment simulations compute a derived column (a regime feature, the rudder's inflow) from
// the simulated states at every step, and only when a model reads it: on the mass-spring-damper
// record, with v' written through a chain of two derived columns of v, the true model still
// free-runs to a small error though the record holds nothing in those columns; and a model that
// reads none of them scores the same to the bit with or without them in the data.
#include <gtest/gtest.h>

#include "methods/gp/segment_simulator.h"
#include "tests/methods/gp_msd_record.h"

namespace usvid::gp {
namespace {

using testing::Linear;
using testing::MsdRecord;

// The record with w = 2 v and h = 0.5 w (= v) among its variables, their columns left zero: a
// simulation that read them from the record rather than from its states would see no damping.
SelectionData WithDerivedSpeed() {
  SelectionData d = MsdRecord(4000);
  const Eigen::Index rows = d.t.size();
  d.names.push_back("w");
  d.variables.push_back(Eigen::VectorXd::Zero(rows));
  d.derived.push_back({3, Expression::Parse("2*v"), {1}});
  d.names.push_back("h");
  d.variables.push_back(Eigen::VectorXd::Zero(rows));
  d.derived.push_back({4, Expression::Parse("0.5*w"), {3}});
  return d;
}

TEST(GpSegmentDerivedTest, ADerivedColumnIsComputedFromTheSimulatedStates) {
  const SelectionData d = WithDerivedSpeed();
  const SegmentSimulator sim(d, {1});
  // v' = -0.2 x - 0.1 h + 0.1 f, h read through w: the true damping only if both are derived.
  const Model through_h = Linear({{0, -0.2}, {4, -0.1}, {2, 0.1}});
  bool diverged = true;
  EXPECT_LT(sim.FreeRunError({&through_h}, diverged), 1e-3);
  EXPECT_FALSE(diverged);
  // Without the damping the record's v is far off: the bound above means something.
  const Model undamped = Linear({{0, -0.2}, {2, 0.1}});
  EXPECT_GT(sim.FreeRunError({&undamped}, diverged), 1e-2);
}

TEST(GpSegmentDerivedTest, ColumnsNoModelReadsLeaveTheErrorUnchanged) {
  const SelectionData with = WithDerivedSpeed();
  const SelectionData without = MsdRecord(4000);
  const Model truth = Linear({{0, -0.2}, {1, -0.1}, {2, 0.1}});
  const std::vector<long> starts = SegmentSimulator::Starts(with.t, 0, 4000, 100);
  bool a = false, b = false;
  EXPECT_EQ(SegmentSimulator(with, {1}).Error({&truth}, starts, 100, a),
            SegmentSimulator(without, {1}).Error({&truth}, starts, 100, b));
}

}  // namespace
}  // namespace usvid::gp
