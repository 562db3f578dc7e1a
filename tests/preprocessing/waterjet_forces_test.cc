// The jets' forces from their measured states (preprocessing/waterjet_forces.h): on an odin-hs
// run, tau_x is the simulator's momentum thrust, the side force opposes the nozzle angle and the
// yaw moment is the side force at the jets' lever arm; jet_flow is both jets' flow; astern, the bucket reverses the thrust at
// the astern efficiency; a record without the jet states is refused, naming what it lacks.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "maneuvers/maneuver_factory.h"
#include "preprocessing/waterjet_forces.h"
#include "simulation/vessel_simulator.h"
#include "simulators/odin_hs.h"

namespace usvid {
namespace {

Dataset JetStates(double rpm, double nozzle, double bucket) {
  Dataset d(Eigen::VectorXd::LinSpaced(3, 0.0, 1.0));
  d.Set("rpm", Eigen::VectorXd::Constant(3, rpm));
  d.Set("nozzle_angle", Eigen::VectorXd::Constant(3, nozzle));
  d.Set("bucket_position", Eigen::VectorXd::Constant(3, bucket));
  return d;
}

TEST(WaterjetForcesTest, ThrustSideForceAndMomentFromTheJetStates) {
  const double* p = OdinHs::kDefaultParams.data();
  // 2000 rpm, nozzle 10 deg to port, bucket open.
  Dataset d = JetStates(2000.0, 10.0 * M_PI / 180.0, 1.0);
  AddWaterjetForces(d);
  const double q = p[OdinHs::kJetFlowPerRpm] * 2000.0, v_jet = q / p[OdinHs::kNozzleArea];
  EXPECT_NEAR(d["tau_x"](1), 2 * OdinHs::kRho * q * v_jet * std::cos(10.0 * M_PI / 180.0),
              1e-6 * d["tau_x"](1));
  EXPECT_NEAR(d["tau_x"](1), OdinHs::SurgeThrust(2000.0, 0.0, 1.0, 10.0 * M_PI / 180.0, p), 1e-6);
  EXPECT_LT(d["tau_y"](1), 0.0);  // the jet's reaction pushes the stern to port
  EXPECT_NEAR(d["tau_n"](1), OdinHs::kJetX * d["tau_y"](1), 1e-9);
  EXPECT_GT(d["tau_n"](1), 0.0);  // and the bow turns to starboard: r > 0
  // The flow through both jets, for the inlet momentum the hull model writes.
  EXPECT_NEAR(d["jet_flow"](1), 2 * q, 1e-12);
  // Astern: the bucket closed gives the astern efficiency of the ahead thrust, reversed.
  Dataset astern = JetStates(2000.0, 0.0, -1.0), ahead = JetStates(2000.0, 0.0, 1.0);
  AddWaterjetForces(astern);
  AddWaterjetForces(ahead);
  EXPECT_NEAR(astern["tau_x"](0) / ahead["tau_x"](0), -p[OdinHs::kAsternEfficiency], 1e-3);
}

TEST(WaterjetForcesTest, OnASimulatedRunTheThrustGoesWithRpmSquared) {
  const VesselSimulator& sim = FindVessel("odin-hs");
  auto m = MakeManeuver("random-steps", sim.Info().actuation, 120, 4);
  Dataset d = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
  AddWaterjetForces(d);
  ASSERT_TRUE(d.Get("tau_x").FullySampled());
  for (Eigen::Index k = 0; k < d.rows(); k += 97) {
    const double rpm = d["rpm"](k), b = d["bucket_position"](k), delta = d["nozzle_angle"](k);
    if (b < 0.99) continue;  // the bucket's smooth switch: compare with it open only
    const double expected = OdinHs::SurgeThrust(rpm, 0.0, b, delta, OdinHs::kDefaultParams.data());
    EXPECT_NEAR(d["tau_x"](k), expected, 1e-9 * std::abs(expected) + 1e-9) << k;
    EXPECT_GT(d["tau_x"](k), 0.0);
  }
}

TEST(WaterjetForcesTest, ARecordWithoutJetStatesIsRefusedNamingThem) {
  Dataset d(Eigen::VectorXd::LinSpaced(3, 0.0, 1.0));
  d.Set("rpm", Eigen::VectorXd::Constant(3, 1000.0));
  try {
    AddWaterjetForces(d);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("lack nozzle_angle, bucket_position"));
  }
  Dataset twice = JetStates(1000.0, 0.0, 1.0);
  AddWaterjetForces(twice);
  EXPECT_THROW(AddWaterjetForces(twice), InputError);  // tau_x is there already
}

}  // namespace
}  // namespace usvid
