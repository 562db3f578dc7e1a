// `refit` (methods/refit/refit.h): a registered vessel's own coefficients fitted to data by
// multiple shooting. When the data come from the vessel with some coefficients changed, the
// refit finds them; what the data do not excite stays at its start (the prior); bad requests
// are refused.
#include "methods/refit/refit.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.h"
#include "maneuvers/maneuver_factory.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

Dataset Simulate(const std::string& vessel, const std::string& maneuver, double seconds,
                 const std::vector<double>& params, uint64_t seed) {
  const VesselSimulator& sim = FindVessel(vessel);
  auto m = MakeManeuver(maneuver, sim.Info().actuation, seconds, seed);
  Dataset d = sim.RunManeuver(*m, params, {}, RunOptions{}).data;
  AddGaussianNoise(d, sim.Info().states, 0.005, seed);
  return d;
}

double Param(const RefitResult& r, const std::string& name) {
  const auto it = std::find(r.names.begin(), r.names.end(), name);
  return r.params.at(it - r.names.begin());
}

// KVLCC2 with 40 % less resistance and a yaw damping N'_r 30 % weaker than published: the
// default refit (R'_0 and the linear hull derivatives) started from the published values finds
// both within 3 %, and the coefficients it was not asked to fit stay as they were.
TEST(RefitTest, FindsTheChangedMmgCoefficients) {
  const VesselInfo& info = FindVessel("kvlcc2").Info();
  std::vector<double> truth = info.default_params;
  const auto index = [&](const std::string& n) {
    return std::find(info.params.begin(), info.params.end(), n) - info.params.begin();
  };
  truth[index("R_0")] *= 0.6;
  truth[index("N_r")] *= 0.7;
  const Dataset data = Simulate("kvlcc2", "zigzag:20/20", 700, truth, 1);
  RefitOptions options;
  options.segment_s = 60;
  const RefitResult r = RefitVessel("kvlcc2", data, info.default_params, options);
  EXPECT_TRUE(r.converged) << r.termination;
  EXPECT_EQ(r.free, (std::vector<std::string>{"R_0", "Y_v", "Y_r", "N_v", "N_r"}));
  EXPECT_NEAR(Param(r, "R_0") / truth[index("R_0")], 1.0, 0.03);
  EXPECT_NEAR(Param(r, "N_r") / truth[index("N_r")], 1.0, 0.03);
  EXPECT_EQ(Param(r, "N_vvv"), info.default_params[index("N_vvv")]);
  EXPECT_EQ(r.channels, (std::vector<std::string>{"u", "v", "r"}));
}

// What the data do not see stays where the prior holds it: at its start, whatever its sign.
// Esso Osaka's wind coefficients act only through a wind the record does not have, so a refit
// that frees C_X1 (-0.822, a head wind's drag) is held by the prior alone: it must stay at
// -0.822, not move to +0.822 (its scale, not its value, which turned the sign of every negative
// coefficient the data left free).
TEST(RefitTest, ThePriorHoldsWhatTheDataDoNotSeeAtItsStartWhateverItsSign) {
  const std::string esso = std::string(USVID_SOURCE_DIR) + "/docs/vessels/files/esso-osaka.yaml";
  const VesselInfo& info = FindVessel(esso).Info();
  const Dataset data = Simulate(esso, "zigzag:20/20", 200, info.default_params, 3);
  RefitOptions options;
  options.free = {"C_X1", "N_r"};
  const RefitResult r = RefitVessel(esso, data, info.default_params, options);
  const auto start = [&](const std::string& n) {
    return info.default_params.at(std::find(info.params.begin(), info.params.end(), n) -
                                  info.params.begin());
  };
  ASSERT_LT(start("C_X1"), 0.0);
  EXPECT_NEAR(Param(r, "C_X1"), start("C_X1"), 1e-6);
  EXPECT_NEAR(Param(r, "N_r") / start("N_r"), 1.0, 0.03);
}

// `seconds` of odin3dof random steps with its linear sway-yaw coupling Nv = 3000 instead of
// 1281.
Dataset OdinWithStrongerNv(double seconds) {
  std::vector<double> truth = FindVessel("odin3dof").Info().default_params;
  truth[7] = 3000.0;  // Nv
  return Simulate("odin3dof", "random-steps", seconds, truth, 2);
}

// Nv fitted alone.
TEST(RefitTest, FitsTheNamedParameterOfAnotherVessel) {
  const VesselInfo& info = FindVessel("odin3dof").Info();
  const Dataset data = OdinWithStrongerNv(200);
  RefitOptions options;
  options.free = {"Nv"};
  const RefitResult r = RefitVessel("odin3dof", data, info.default_params, options);
  EXPECT_NEAR(Param(r, "Nv"), 3000.0, 90.0);
}

// On a record longer than max_rows the segments fitted are a share spread over it: as many
// residuals as max_rows rows hold (within a segment), and Nv still found.
TEST(RefitTest, ABoundedShareOfALongRecordFindsTheParameter) {
  const VesselInfo& info = FindVessel("odin3dof").Info();
  const Dataset data = OdinWithStrongerNv(800);
  RefitOptions options;
  options.free = {"Nv"};
  options.max_rows = 4000;
  ASSERT_GT(data.rows(), 3 * options.max_rows);
  const RefitResult r = RefitVessel("odin3dof", data, info.default_params, options);
  const double rows = static_cast<double>(r.residuals) / 3.0;  // u, v, r at each row
  const double per_segment = rows / r.segments;
  EXPECT_NEAR(rows, 4000.0, per_segment);
  EXPECT_NEAR(Param(r, "Nv"), 3000.0, 90.0);
}

TEST(RefitTest, RefusesWhatItCannotFit) {
  const VesselInfo& info = FindVessel("odin3dof").Info();
  const Dataset data = Simulate("odin3dof", "random-steps", 30, info.default_params, 3);
  RefitOptions options;
  options.free = {"Nv", "warp_drive"};
  EXPECT_THROW(RefitVessel("odin3dof", data, info.default_params, options), InputError);
  options.free = {};
  EXPECT_THROW(RefitVessel("odin3dof", data, {1.0, 2.0}, options), InputError);
  // odin-hs needs its jets' states (rpm, nozzle, bucket) and inputs, which odin3dof data lack.
  EXPECT_THROW(RefitVessel("odin-hs", data, FindVessel("odin-hs").Info().default_params, options),
               InputError);
  Dataset no_sway = data;
  no_sway.Remove("v");
  EXPECT_THROW(RefitVessel("odin3dof", no_sway, info.default_params, options), InputError);
}

}  // namespace
}  // namespace usvid
