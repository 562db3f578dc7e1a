// GP's simulation refit (methods/gp/simulation_refit.h) on the mass-spring-damper
// x' = v, v' = -0.2 x - 0.1 v + 0.1 f, both states integrated: weights that are wrong by 20-40 %
// are fitted back to the truth by the states' simulation error alone (on the first 160 s, checked
// on the last 40 s), the truth stays where it is, and weights that the last 40 s contradict are
// not kept.
#include <gtest/gtest.h>

#include <cmath>

#include "methods/gp/simulation_refit.h"
#include "tests/methods/gp_msd_record.h"

namespace usvid::gp {
namespace {

using testing::Linear;

// 200 s; the damping `damping_after` from 160 s on.
SelectionData Msd(double damping_after = 0.1) {
  return testing::MsdRecord(4000, 3200, damping_after);
}

TEST(GpSimulationRefitTest, WrongWeightsAreFittedBackToTheTruthBySimulationError) {
  const SelectionData d = Msd();
  std::vector<Model> models = {Linear({{1, 1.0}}),
                               Linear({{0, -0.2 * 1.3}, {1, -0.1 * 0.6}, {2, 0.1 * 1.2}}, 0.01)};
  const SimulationRefit r = RefitBySimulation(d, {0, 1}, models, {10.0, 30, 3200});
  ASSERT_TRUE(r.accepted) << r.reason;
  EXPECT_EQ(r.segments, 15);  // 10 s segments that end before 160 s
  EXPECT_EQ(r.validation_segments, 3);
  EXPECT_LT(r.validation_error_after, 1e-4 * r.validation_error_before);
  EXPECT_EQ(r.parameters, 2 + 4);
  EXPECT_LT(r.final_error, 1e-4 * r.initial_error);
  EXPECT_LT(r.free_run_error_after, r.free_run_error_before);
  // The Euler steps of 1 ms that made the data are the only model error left.
  EXPECT_NEAR(models[0].weights[0], 1.0, 2e-3);
  EXPECT_NEAR(models[1].weights[0], -0.2, 2e-3);
  EXPECT_NEAR(models[1].weights[1], -0.1, 2e-3);
  EXPECT_NEAR(models[1].weights[2], 0.1, 2e-3);
  EXPECT_NEAR(models[1].bias, 0.0, 1e-3);
}

TEST(GpSimulationRefitTest, TheTruthStaysWhereItIs) {
  const SelectionData d = Msd();
  std::vector<Model> models = {Linear({{1, 1.0}}), Linear({{0, -0.2}, {1, -0.1}, {2, 0.1}})};
  RefitBySimulation(d, {0, 1}, models, {10.0, 30, 3200});
  EXPECT_NEAR(models[1].weights[0], -0.2, 2e-3);
  EXPECT_NEAR(models[1].weights[1], -0.1, 2e-3);
  EXPECT_NEAR(models[1].weights[2], 0.1, 2e-3);
}

// The damping triples at 160 s; the model has the later damping. Fitted on the first 160 s, the
// weights would move toward the earlier one, which the last 40 s contradict.
TEST(GpSimulationRefitTest, WeightsTheValidationPartContradictsAreNotKept) {
  const SelectionData d = Msd(0.3);
  std::vector<Model> models = {Linear({{1, 1.0}}), Linear({{0, -0.2}, {1, -0.3}, {2, 0.1}})};
  const SimulationRefit r = RefitBySimulation(d, {0, 1}, models, {10.0, 30, 3200});
  EXPECT_LT(r.final_error, 0.1 * r.initial_error);  // the first 160 s alone favour the change
  EXPECT_GT(r.validation_error_after, r.validation_error_before);
  EXPECT_FALSE(r.accepted);
  EXPECT_EQ(models[1].weights[1], -0.3);
}

TEST(GpSimulationRefitTest, AMismatchedCallChangesNothing) {
  const SelectionData d = Msd();
  std::vector<Model> models = {Linear({{1, 1.0}})};
  const SimulationRefit r = RefitBySimulation(d, {0, 1}, models, {10.0, 30, 3200});
  EXPECT_FALSE(r.accepted);
  EXPECT_EQ(models[0].weights[0], 1.0);
}

}  // namespace
}  // namespace usvid::gp
