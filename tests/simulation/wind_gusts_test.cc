// Unmeasured gusty wind (simulation/wind_gusts.h): a beam wind on odin-hs holding its course under
// the autopilot pushes it to leeward and makes the autopilot hold a yaw command against the
// wind's moment; the wind is in no channel of the record; the same seed gives the same record;
// vessels it cannot act on and bad specs are refused.
#include "simulation/wind_gusts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "maneuvers/maneuver_factory.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

// odin-hs holding its initial course north for 300 s (the autopilot's first course change comes
// after 500 s), under `gusts` ("" for calm).
Dataset HoldCourse(const std::string& gusts, uint64_t seed = 3) {
  const VesselSimulator& sim = FindVessel("odin-hs");
  const VesselInfo& info = sim.Info();
  auto m = MakeManeuver("autopilot:1000", info.actuation, 300, seed);
  RunOptions run;
  if (!gusts.empty())
    run.disturbance = GustDisturbance(MakeWindGusts(info, gusts, seed, "t"), seed);
  return sim.RunManeuver(*m, info.default_params, {}, run).data;
}

TEST(WindGustsTest, ABeamWindPushesTheVesselToLeeward) {
  const Dataset calm = HoldCourse(""), windy = HoldCourse("15:90");  // from the east
  const Eigen::Index last = calm.rows() - 1;
  // Pushed west: tens of metres in five minutes, while the heading is held within a degree.
  EXPECT_LT(windy["east"](last) - calm["east"](last), -20.0);
  const Eigen::VectorXd& psi = windy["psi"];
  EXPECT_LT(psi.tail(windy.rows() / 2).cwiseAbs().maxCoeff(), std::numbers::pi / 180);
  // The autopilot holds the nozzle against the wind's yaw moment.
  EXPECT_GT(std::abs(windy["nozzle"].tail(windy.rows() / 2).mean()),
            10 * std::abs(calm["nozzle"].tail(calm.rows() / 2).mean()) + 1e-4);
  std::vector<std::string> names, calm_names;
  for (const Channel& c : windy.channels()) names.push_back(c.name);
  for (const Channel& c : calm.channels()) calm_names.push_back(c.name);
  EXPECT_EQ(names, calm_names) << "the wind is in no channel";
  EXPECT_EQ(HoldCourse("15:90")["north"], windy["north"]);
}

TEST(WindGustsTest, RefusesWhatItCannotActOn) {
  const VesselInfo& odin = FindVessel("odin3dof").Info();
  EXPECT_NO_THROW(MakeWindGusts(odin, "10", 1, "--gusts"));
  EXPECT_THROW(MakeWindGusts(FindVessel("msd").Info(), "10", 1, "--gusts"), InputError);
  EXPECT_THROW(MakeWindGusts(odin, "-1", 1, "--gusts"), InputError);
  EXPECT_THROW(MakeWindGusts(odin, "50", 1, "--gusts"), InputError);
  EXPECT_THROW(MakeWindGusts(odin, "10:x", 1, "--gusts"), InputError);
}

}  // namespace
}  // namespace usvid
