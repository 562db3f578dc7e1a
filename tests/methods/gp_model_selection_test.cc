// GP's model choice by short-horizon simulation (methods/gp/model_selection.h), on the
// mass-spring-damper v' = -0.2 x - 0.1 v + 0.1 f (x measured, no equation of its own): among
// candidates whose equations fit about equally, the one that simulates the validation part is
// chosen, a candidate whose free run blows up is never chosen, and of two that simulate equally
// well the smaller is.
#include <gtest/gtest.h>

#include <cmath>

#include "methods/gp/model_selection.h"
#include "tests/methods/gp_msd_record.h"

namespace usvid::gp {
namespace {

using testing::Linear;

SelectionData Msd() {
  SelectionData d = testing::MsdRecord(6000);  // 300 s
  d.validation_begin = 4800;
  return d;
}

TEST(GpModelSelectionTest, ChoosesTheModelThatSimulatesAndNeverOneThatDiverges) {
  const SelectionData d = Msd();
  StateCandidates v{"v",
                    {Linear({{0, -0.2}, {1, 0.6}, {2, 0.1}}),  // undamped: grows without end
                     Linear({{0, -0.2}, {2, 0.1}}),            // no damping term
                     Linear({{0, -0.2}, {1, -0.1}, {2, 0.1}})}};
  const Selection s = SelectModels(d, {v});
  ASSERT_EQ(s.chosen.size(), 1u);
  EXPECT_EQ(s.chosen[0], 2u);
  EXPECT_FALSE(s.free_run_diverged);
  // The true model simulates the validation part to 0.1 % of its variance (x is held at its
  // sampled value within a step: the rest).
  EXPECT_LT(s.candidate_scores[0][2].score, 1e-3);
  EXPECT_GT(s.candidate_scores[0][0].score, 100 * s.candidate_scores[0][2].score);
}

TEST(GpModelSelectionTest, OfTwoThatSimulateAlikeTheSmallerIsChosen) {
  const SelectionData d = Msd();
  // The second adds a term of weight 1e-9: no visible difference in simulation.
  StateCandidates v{"v",
                    {Linear({{0, -0.2}, {1, -0.1}, {2, 0.1}, {0, 1e-9}}),
                     Linear({{0, -0.2}, {1, -0.1}, {2, 0.1}})}};
  EXPECT_EQ(SelectModels(d, {v}).chosen[0], 1u);
}

TEST(GpModelSelectionTest, AStateThatIsNoVariableIsRefused) {
  StateCandidates w{"w", {Linear({{0, 1.0}})}};
  EXPECT_THROW(SelectModels(Msd(), {w}), std::exception);
}

}  // namespace
}  // namespace usvid::gp
