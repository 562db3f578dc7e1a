// The step grid's fixed hold (stepgrid:T/Y/H, maneuvers/step_grid.h): every step held H seconds,
// so the grid's length is known before the run, T (1 + 2 Y) H; a hold too short for any steady
// window is refused where the grid is built, naming the hold and the time a step needs.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "maneuvers/maneuver_factory.h"
#include "maneuvers/step_grid.h"
#include "simulation/vessel_simulator.h"

namespace usvid {
namespace {

using ::testing::HasSubstr;

class StepGridHoldTest : public ::testing::Test {};

// A fixed hold runs the grid as a schedule: 4 x (1 + 2 x 2) steps of 20 s, 400 s, each step
// starting 20 s after the one before, the thrust stepping up through the levels.
TEST_F(StepGridHoldTest, FixedHoldRunsTheGridInItsKnownLength) {
  const VesselSimulator& sim = FindVessel("odin-hs");
  auto grid = MakeManeuver("stepgrid:4/2/20", sim.Info().actuation, 0.0, 1);
  EXPECT_EQ(grid->Spec(), "stepgrid:4/2/20");
  const SimulationResult run = sim.RunManeuver(*grid, sim.Info().default_params, {}, RunOptions{});
  EXPECT_NEAR(run.data.duration(), 400.0, 0.1);
  const nlohmann::json report = grid->Report();
  ASSERT_EQ(report.at("steps").size(), 20u);
  EXPECT_EQ(report.at("completed_steps"), 20);
  for (size_t k = 0; k < 20; ++k)
    EXPECT_NEAR(report["steps"][k]["start_s"].get<double>(), 20.0 * static_cast<double>(k), 0.06)
        << k;
  EXPECT_LT(report["steps"][0]["thrust"].get<double>(),
            report["steps"][19]["thrust"].get<double>());
}

// A hold shorter than a step needs (5 s to settle, 3 s of steady state for eb-lr's window) is
// bad input, naming the hold and the time needed; an unusable hold is refused too.
TEST_F(StepGridHoldTest, HoldTooShortForAnySteadyWindowIsRefused) {
  const Actuation& act = FindVessel("odin3dof").Info().actuation;
  try {
    MakeManeuver("stepgrid:4/3/5", act, 0.0, 1);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("a hold of 5 s is too short for any steady window"));
    EXPECT_THAT(e.what(), HasSubstr("at least 8 s"));
  }
  EXPECT_THROW(MakeManeuver("stepgrid:4/3/0", act, 0.0, 1), InputError);
  EXPECT_THROW(MakeManeuver("stepgrid:4/3/-20", act, 0.0, 1), InputError);
  EXPECT_THROW(MakeManeuver("stepgrid:4/3/20/1", act, 0.0, 1), InputError);
  EXPECT_NO_THROW(MakeManeuver("stepgrid:4/3/8", act, 0.0, 1));
  EXPECT_EQ(MakeManeuver("stepgrid:4/3", act, 0.0, 1)->Spec(), "stepgrid:4/3");
}

}  // namespace
}  // namespace usvid
