// A closed-loop maneuver records the commands it issued; replaying them open-loop with
// `simulate --inputs` reproduces the run (the controller runs at the output rate and its
// commands are held, so the recorded data are the whole truth). This is what identification and
// diagnosis rely on when they re-simulate measured data.
#include <gtest/gtest.h>

#include "maneuvers/maneuver_factory.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

class ClosedLoopReplayTest : public ::testing::Test {};

TEST_F(ClosedLoopReplayTest, ReplayingRecordedCommandsReproducesTheRun) {
  for (const std::string vessel : {"odin3dof", "eb2dof", "msd"}) {
    for (const std::string effect : {"", "input_delay=0.3", "actuator_lag=0.7"}) {
      const VesselSimulator& sim = FindVessel(vessel);
      const std::string spec = vessel == "msd" ? "prbs" : "zigzag:20/20";
      auto m = MakeManeuver(spec, sim.Info().actuation, 120, 2);
      const auto effects = ValuesOf(effect.empty() ? std::vector<Effect>{}
                                                   : std::vector<Effect>{ParseEffect(effect, 1)});
      const SimulationResult run = sim.RunManeuver(*m, sim.Info().default_params, effects, {});
      const SimulationResult replay =
          sim.RunInputs(run.data, sim.Info().default_params, effects, {});
      ASSERT_EQ(replay.data.rows(), run.data.rows());
      // Before the delay has passed, the replay cannot know the commands of the run-in.
      const Eigen::Index skip = effect.empty() ? 0 : 40;
      for (const std::string& s : sim.Info().states) {
        const Eigen::VectorXd a = run.data[s].tail(run.data.rows() - skip);
        const Eigen::VectorXd b = replay.data[s].tail(run.data.rows() - skip);
        const double range = a.maxCoeff() - a.minCoeff() + 1e-9;
        EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-6 * range)
            << vessel << " " << effect << " " << s;
      }
    }
  }
}

}  // namespace
}  // namespace usvid
