// Maneuver design (design/): the Fisher information of a method's parameters for a maneuver,
// through the simulator. It obeys what information is (it scales as 1 / noise^2; a prior caps
// the predicted sd), and it predicts: the spread of 8 seeded fossen-ceres fits on odin3dof
// random steps is what the Cramer-Rao bound says, within a factor of 1.5.
#include <gtest/gtest.h>

#include <cmath>

#include "design/information.h"
#include "design/optimize.h"
#include "design/spread_check.h"
#include "core/error.h"
#include "simulation/vessel_simulator.h"

namespace usvid::design {
namespace {

NoiseModel NoiseOn(const std::string& vessel, const std::string& maneuver, double seconds,
                   double noise) {
  return ReferenceNoise(SimulateManeuver(vessel, maneuver, seconds, 1),
                        FindVessel(vessel).Info().states, noise);
}

// Twice the noise, a quarter of the information: log det falls by 2 n ln 2 (n = 10 parameters),
// and every predicted sd doubles. fossen-ceres has no prior to blur it.
TEST(InformationTest, ScalesAsOneOverTheNoiseVariance) {
  const auto a = InformationOf("odin3dof", "fossen-ceres", "random-steps", 300,
                               NoiseOn("odin3dof", "random-steps", 300, 0.005));
  const auto b = InformationOf("odin3dof", "fossen-ceres", "random-steps", 300,
                               NoiseOn("odin3dof", "random-steps", 300, 0.01));
  ASSERT_EQ(a.names.size(), 10u);
  EXPECT_NEAR(a.log_det - b.log_det, 20.0 * std::log(2.0), 1e-6);
  for (size_t i = 0; i < a.sd.size(); ++i) EXPECT_NEAR(b.sd[i] / a.sd[i], 2.0, 1e-6) << a.names[i];
}

// refit's prior (relative sd 0.5) is information of its own: no predicted relative sd exceeds
// it, even for a coefficient a short zig-zag barely excites.
TEST(InformationTest, RefitsPriorCapsThePredictedSd) {
  const auto m = InformationOf("kvlcc2", "refit", "zigzag:20/20", 300,
                               NoiseOn("kvlcc2", "zigzag:20/20", 300, 0.005));
  EXPECT_EQ(m.names, (std::vector<std::string>{"R_0", "Y_v", "Y_r", "N_v", "N_r"}));
  for (size_t i = 0; i < m.names.size(); ++i) EXPECT_LE(m.relative_sd[i], 0.5) << m.names[i];
  ASSERT_EQ(m.weakest.size(), 2u);
  EXPECT_LE(m.weakest[0].eigenvalue, m.weakest[1].eigenvalue);
}

// Issue 22's acceptance: fossen-ceres on odin3dof random steps, 0.5 % noise, 600 s; the median
// over parameters of predicted sd / the sd of 8 seeded fits is within [0.67, 1.5].
TEST(SpreadCheckTest, FossenFitsScatterAsPredictedOnRandomSteps) {
  const NoiseModel noise = NoiseOn("odin3dof", "random-steps", 600, 0.005);
  const auto m = InformationOf("odin3dof", "fossen-ceres", "random-steps", 600, noise);
  const SpreadCheck c = CheckSpread("odin3dof", "fossen-ceres", m, 600, noise, 8, 2);
  EXPECT_EQ(c.failed, 0);
  EXPECT_GE(c.median_ratio, 0.67);
  EXPECT_LE(c.median_ratio, 1.5);
}

TEST(InformationTest, RefusesWhatItCannotDesign) {
  const NoiseModel noise = NoiseOn("odin3dof", "random-steps", 60, 0.005);
  EXPECT_THROW(InformationOf("odin3dof", "gp", "random-steps", 60, noise), InputError);
  EXPECT_THROW(InformationOf("odin3dof", "sindy", "random-steps", 60, noise), InputError);
  EXPECT_THROW(InformationOf("kvlcc2", "fossen-ceres", "zigzag", 60, noise), InputError);
  EXPECT_THROW(InformationOf("odin3dof", "fossen-ceres", "warp", 60, noise), InputError);
  EXPECT_THROW(InformationOf("odin3dof", "fossen-ceres", "random-steps", 0, noise), InputError);
  EXPECT_THROW(ReferenceNoise(SimulateManeuver("odin3dof", "prbs", 60, 1), {"u"}, 0.0),
               InputError);
}

// The PRBS clock searched on odin3dof (fossen-ceres, 600 s): the best clock's information beats
// the default's (4 s), and nothing is searched for a turning circle.
TEST(OptimizeTest, FindsAPrbsClockBetterThanTheDefault) {
  const NoiseModel noise = NoiseOn("odin3dof", "random-steps", 600, 0.005);
  const auto built_in = InformationOf("odin3dof", "fossen-ceres", "prbs", 600, noise);
  const auto best = OptimizeManeuver("odin3dof", "fossen-ceres", "prbs", 600, noise);
  ASSERT_TRUE(best.has_value());
  EXPECT_GT(best->log_det, built_in.log_det);
  EXPECT_EQ(best->maneuver.rfind("prbs:", 0), 0u);
  EXPECT_FALSE(OptimizeManeuver("odin3dof", "fossen-ceres", "turning", 600, noise).has_value());
}

}  // namespace
}  // namespace usvid::design
