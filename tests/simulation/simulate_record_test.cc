// One simulated record (simulation/simulate_record.h), the same for `usvid simulate`, a suite
// and Python: the output grid rises to the fastest sensor, the truth names the noise put on
// every measured channel, a seed gives the same record twice and another seed other noise, and a
// recipe with nothing to drive the vessel is refused.
#include "simulation/simulate_record.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

RecordRecipe ZigZag(double noise, uint64_t seed) {
  RecordRecipe r;
  r.vessel = "odin3dof";
  r.maneuver = "zigzag:20/20";
  r.duration_s = 40.0;
  r.sensors.noise = noise;
  r.seed = seed;
  return r;
}

TEST(SimulateRecordTest, TheGridRisesToTheFastestSensor) {
  RecordRecipe r = ZigZag(0.0, 1);
  r.sensors.rates = {"imu=50"};
  const SimulatedRecord record = SimulateRecord(r);
  EXPECT_EQ(record.truth.at("rate_hz").get<double>(), 50.0);
  EXPECT_NEAR(record.data.duration(), 40.0, 1e-9);
}

TEST(SimulateRecordTest, TheTruthNamesTheNoiseOnEveryMeasuredChannel) {
  const SimulatedRecord record = SimulateRecord(ZigZag(0.01, 3));
  const VesselInfo& info = FindVessel("odin3dof").Info();
  for (const std::string& state : info.states) {
    ASSERT_TRUE(record.truth.at("noise").at("sd").contains(state)) << state;
    EXPECT_GT(record.truth["noise"]["sd"][state].get<double>(), 0.0) << state;
  }
  EXPECT_EQ(record.truth.at("maneuver").at("spec"), "zigzag:20/20");
  EXPECT_FALSE(record.diverged);
}

TEST(SimulateRecordTest, ASeedGivesTheSameRecordAndAnotherSeedOtherNoise) {
  const std::string state = FindVessel("odin3dof").Info().states.front();
  const Dataset a = SimulateRecord(ZigZag(0.01, 5)).data;
  const Dataset b = SimulateRecord(ZigZag(0.01, 5)).data;
  const Dataset c = SimulateRecord(ZigZag(0.01, 6)).data;
  EXPECT_EQ(a[state], b[state]);
  EXPECT_NE(a[state], c[state]);
}

TEST(SimulateRecordTest, NothingToDriveTheVesselIsRefused) {
  RecordRecipe r = ZigZag(0.0, 1);
  r.maneuver.clear();
  EXPECT_THROW(SimulateRecord(r), InputError);
}

}  // namespace
}  // namespace usvid
