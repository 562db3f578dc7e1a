// The diagnosis's parts (diagnosis/measured_data.h): the record is split by time, the last third
// held out; on a record longer than max_fit_rows the effects are fitted on the training part's
// last max_fit_rows rows and scored on the held-out part's first, the two windows meeting at the
// split, so that the fits and the scoring cost the same however long the log.
#include "diagnosis/measured_data.h"

#include <gtest/gtest.h>

#include "maneuvers/maneuver_factory.h"
#include "simulation/vessel_simulator.h"

namespace usvid::diagnosis {
namespace {

Dataset Record(double seconds) {
  const VesselSimulator& sim = FindVessel("odin3dof");
  auto m = MakeManeuver("random-steps", sim.Info().actuation, seconds, 3);
  return sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
}

TEST(MeasuredDataTest, ALongRecordIsFittedAndScoredOnBoundedWindowsAtTheSplit) {
  const Dataset data = Record(300.0);
  const VesselSimulator& sim = FindVessel("odin3dof");
  SplitOptions o;
  o.max_fit_rows = 400;
  ASSERT_GT(data.rows() / 3, 2 * o.max_fit_rows);
  const MeasuredData d = PrepareMeasuredData(data, sim, sim.Info().default_params, o);
  EXPECT_EQ(d.train.begin, 0);
  EXPECT_EQ(d.train.end, d.heldout.begin);
  EXPECT_EQ(d.fit.end, d.train.end);  // the training part's last rows
  EXPECT_LE(d.fit.end - d.fit.begin, o.max_fit_rows);
  EXPECT_GT(d.fit.end - d.fit.begin, o.max_fit_rows / 2);
  EXPECT_EQ(d.heldout.end - d.heldout.begin, o.max_fit_rows);  // the held-out part's first rows
  EXPECT_EQ(d.fit.starts.front(), d.fit.begin);
  EXPECT_EQ(d.heldout.starts.front(), d.heldout.begin);
  EXPECT_EQ(d.all.end, data.rows());  // what the show step analyses: every row

  o.max_fit_rows = 0;  // all rows
  const MeasuredData whole = PrepareMeasuredData(data, sim, sim.Info().default_params, o);
  EXPECT_EQ(whole.fit.begin, 0);
  EXPECT_EQ(whole.fit.end, whole.train.end);
  EXPECT_EQ(whole.heldout.end, data.rows());
  EXPECT_EQ(whole.heldout.begin, d.heldout.begin);  // the split is the same
}

}  // namespace
}  // namespace usvid::diagnosis
