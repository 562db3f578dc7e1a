// Grey-box GP-SR (methods/gp/grey_box.h): GP's corrections to a known vessel. Data from
// odin3dof with a cross-flow yaw term it lacks, r' += 0.05 |v| v: the correction to r carries
// that term's shape (an odd function of v), the free runs of the held-out parts fall to the
// noise's level, and nothing is added to u' or v', which lack nothing. From the vessel as it
// is, nothing is added. A free run that leaves its bounds never keeps a correction.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "core/expression.h"
#include "methods/gp/grey_box.h"
#include "simulation/vessel_simulator.h"
#include "tests/methods/odin3dof_record.h"

namespace usvid {
namespace {

Dataset Simulate(const std::vector<Effect>& effects, double seconds, uint64_t seed) {
  return fixtures::Odin3dofRandomSteps(effects, seconds, seed);
}

gp::GreyBoxOptions SmallSearch() {
  gp::GreyBoxOptions o;
  o.search.population = 500;
  o.search.generations = 20;
  o.search.functions = {gp::Op::kAdd, gp::Op::kSub, gp::Op::kMul, gp::Op::kAbs};
  o.search.seed = 1;
  o.search.threads = 2;
  return o;
}

using fixtures::kCrossFlowYaw;

// The sum of the kept corrections to `state` at (v, everything else 0).
double CorrectionAt(const std::vector<Effect>& terms, const std::string& state, double v) {
  double sum = 0.0;
  for (const Effect& e : terms) {
    if (e.state != state) continue;
    const Expression x = Expression::Parse(e.term);
    std::vector<double> values;
    for (const std::string& name : x.Variables()) values.push_back(name == "v" ? v : 0.0);
    sum += e.at("coefficient") * x.Evaluate(values);
  }
  return sum;
}

TEST(GpGreyBoxTest, CorrectsTheVesselsYawByTheCrossFlowTermItLacksAndNothingElse) {
  const Dataset data = Simulate({kCrossFlowYaw}, 600, 3);
  const gp::GreyBoxResult r = gp::IdentifyGreyBox(
      "odin3dof", FindVessel("odin3dof").Info().default_params, data, SmallSearch());
  ASSERT_EQ(r.corrections.size(), 1u) << "only r lacks a term";
  EXPECT_TRUE(r.corrections.contains("r"));
  // The free runs of the held-out parts: from the vessel's own error to a hundredth of it.
  EXPECT_LT(r.free_run_error, 0.01 * r.vessel_free_run_error);
  // The correction is the missing term's shape over the sway speeds the record holds
  // (|v| below 1.5 m/s), whatever terms GP wrote it with.
  for (double v : {-1.0, -0.5, 0.5, 1.0})
    EXPECT_NEAR(CorrectionAt(r.terms, "r", v), 0.05 * std::abs(v) * v, 0.01) << "v = " << v;
}

TEST(GpGreyBoxTest, AddsNothingToTheVesselAsItIs) {
  const Dataset data = Simulate({}, 600, 4);
  const gp::GreyBoxResult r = gp::IdentifyGreyBox(
      "odin3dof", FindVessel("odin3dof").Info().default_params, data, SmallSearch());
  EXPECT_TRUE(r.terms.empty()) << r.corrections.size() << " corrections";
  EXPECT_EQ(r.free_run_error, r.vessel_free_run_error);
  EXPECT_FALSE(r.tried.empty()) << "every state's front was tried";
}

TEST(GpGreyBoxTest, RefusesARecordWithoutTheVesselsStates) {
  Dataset data = Simulate({}, 60, 5);
  Dataset no_v;
  no_v.SetTime(data.t());
  for (const char* c : {"u", "r", "tau_x", "tau_y", "tau_n"}) no_v.Set(c, data[c]);
  try {
    gp::IdentifyGreyBox("odin3dof", FindVessel("odin3dof").Info().default_params, no_v,
                        SmallSearch());
    FAIL() << "a record without v was fitted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'v'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace usvid
