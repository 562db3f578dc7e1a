// `hybrid` (methods/hybrid/hybrid.h): a registered vessel plus the terms its physics lacks.
// Data from odin3dof with a cross-flow yaw term it does not have, r' += 0.05 |v| v: the hybrid
// adds exactly that term, with its coefficient, and nothing else; from the vessel as it is, it
// adds nothing. A free run, which checks each term, tells a missing term from an unstable one.
// The proposals (FROLS) find the terms of a known residual, and a speed-scaled vessel's library
// has the MMG form.
#include "methods/hybrid/hybrid.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/records.h"
#include "effects/effect_values.h"
#include "maneuvers/maneuver_factory.h"
#include "methods/hybrid/free_coefficient_shape.h"
#include "methods/hybrid/heldout_free_run.h"
#include "methods/hybrid/term_proposals.h"
#include "preprocessing/pipeline.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"
#include "tests/methods/odin3dof_record.h"

namespace usvid {
namespace {

Dataset Simulate(const std::vector<Effect>& effects, double seconds, uint64_t seed) {
  return fixtures::Odin3dofRandomSteps(effects, seconds, seed);
}

using fixtures::kCrossFlowYaw;

TEST(HybridTest, AddsTheMissingCrossFlowYawTermAndOnlyThat) {
  const Dataset data = Simulate({kCrossFlowYaw}, 900, 3);
  hybrid::HybridOptions options;
  options.refit.threads = 2;
  const hybrid::HybridResult h = hybrid::IdentifyHybrid(
      "odin3dof", data, FindVessel("odin3dof").Info().default_params, options);
  ASSERT_EQ(h.fit.terms.size(), 1u);
  EXPECT_EQ(h.fit.terms[0].state, "r");
  EXPECT_EQ(h.fit.terms[0].term, "abs(v)*v");
  EXPECT_NEAR(h.fit.terms[0].at("coefficient"), 0.05, 0.005);
  // With it, the held-out error falls to the noise (E about 1 in units of the noise variance).
  EXPECT_LT(h.heldout_error, 0.01 * h.vessel_heldout_error);
  EXPECT_LT(h.heldout_error, 1.5);
  ASSERT_GE(h.rounds.size(), 2u);
  EXPECT_GT(h.rounds[0].likelihood_ratio, options.critical_ratio);
  EXPECT_EQ(h.rounds.back().chosen, -1);  // the next best term is not worth its coefficient
}

TEST(HybridTest, SearchesOnAShareOfTheRowsAndFitsTheModelOnAllOfThem) {
  // search_rows bounds each proposal's fit and score; fit_rows (0: all) the final fit's.
  const Dataset data = Simulate({kCrossFlowYaw}, 900, 3);
  hybrid::HybridOptions options;
  options.refit.threads = 2;
  options.refit.max_rows = 0;
  options.search_rows = data.rows() / 8;
  const hybrid::HybridResult h = hybrid::IdentifyHybrid(
      "odin3dof", data, FindVessel("odin3dof").Info().default_params, options);
  ASSERT_EQ(h.fit.terms.size(), 1u);
  EXPECT_EQ(h.fit.terms[0].term, "abs(v)*v");
  EXPECT_NEAR(h.fit.terms[0].at("coefficient"), 0.05, 0.005);
  // Three states' residuals on nearly every row (each segment's first row is its estimated
  // start), not on the search's eighth.
  EXPECT_GT(h.fit.residuals, 3 * data.rows() * 9 / 10);
}

TEST(HybridTest, AddsNothingToTheVesselAsItIs) {
  const Dataset data = Simulate({}, 600, 4);
  hybrid::HybridOptions options;
  options.refit.threads = 2;
  const hybrid::HybridResult h = hybrid::IdentifyHybrid(
      "odin3dof", data, FindVessel("odin3dof").Info().default_params, options);
  EXPECT_TRUE(h.fit.terms.empty());
  ASSERT_EQ(h.rounds.size(), 1u);
  EXPECT_LT(h.rounds[0].likelihood_ratio, options.critical_ratio);
}

TEST(HybridTest, AFreeRunChecksTheModelOnEachHeldOutRecordFromItsOwnStart) {
  // Two records of odin3dof with the cross-flow term, joined: the vessel with the term free-runs
  // them to the noise; without it the error is larger; with an unstable yaw term the runs leave
  // their bounds, which multiple shooting from each segment's measured state would not see.
  // Each record runs from its own first row: run across the join, the second would start from
  // the first one's end.
  const VesselInfo& info = FindVessel("odin3dof").Info();
  const Dataset joined =
      JoinRecords({Simulate({kCrossFlowYaw}, 300, 7), Simulate({kCrossFlowYaw}, 300, 8)});
  const std::vector<std::string> states = {"u", "v", "r"};
  const double with_term =
      hybrid::HeldoutFreeRunError("odin3dof", joined, info.default_params, {kCrossFlowYaw}, states);
  const double without =
      hybrid::HeldoutFreeRunError("odin3dof", joined, info.default_params, {}, states);
  EXPECT_LT(with_term, 0.01);
  EXPECT_GT(without, 10.0 * with_term);
  // A state logged at a third of the rate (its other rows not sampled) is compared where it was.
  Dataset sparse = joined;
  Channel::Mask every_third = Channel::Mask::Constant(sparse.rows(), false);
  Eigen::VectorXd u = Eigen::VectorXd::Constant(sparse.rows(), std::nan(""));
  for (Eigen::Index k = 0; k < sparse.rows(); k += 3) {
    every_third(k) = true;
    u(k) = sparse["u"](k);
  }
  sparse.Set("u", u, every_third);
  EXPECT_NEAR(
      hybrid::HeldoutFreeRunError("odin3dof", sparse, info.default_params, {kCrossFlowYaw}, states),
      with_term, 0.005);
  // A yaw moment that grows with the rate squared the wrong way, as the Esso Osaka runs proposed.
  const Effect unstable{EffectKind::kMissingTerm, {{"coefficient", 10.0}}, {}, "r", "abs(r)*r"};
  const double e = hybrid::HeldoutFreeRunError("odin3dof", joined, info.default_params,
                                               {kCrossFlowYaw, unstable}, states);
  EXPECT_TRUE(std::isinf(e)) << e;
}

TEST(HybridTest, AFreeRunThatMayStopRunsTheLikelyWorstRecordFirst) {
  // Three records, the last of a vessel with twice the cross-flow term: the model with the term
  // once free-runs the first two to the noise and misses the third. Asked only whether its error
  // exceeds half of what it is, it must run the third to know; run in the data's order, it runs
  // all three, and run the hardest first (as a similar model found them), that one alone. A run
  // that finishes has the same error, bit for bit, in either order.
  const VesselInfo& info = FindVessel("odin3dof").Info();
  Effect twice = kCrossFlowYaw;
  twice.parameters["coefficient"] *= 2.0;
  const Dataset joined =
      JoinRecords({Simulate({kCrossFlowYaw}, 200, 7), Simulate({kCrossFlowYaw}, 200, 8),
                   Simulate({twice}, 200, 9)});
  const std::vector<std::string> states = {"u", "v", "r"};
  const auto run = [&](double stop_above, const std::vector<double>& likely) {
    return hybrid::HeldoutFreeRuns("odin3dof", joined, info.default_params, {kCrossFlowYaw}, states,
                                   stop_above, likely);
  };
  const hybrid::HeldoutFreeRun whole = run(std::numeric_limits<double>::infinity(), {});
  ASSERT_EQ(whole.per_record.size(), 3u);
  EXPECT_GT(whole.per_record[2], 10.0 * (whole.per_record[0] + whole.per_record[1]));
  const std::vector<double> likely = whole.per_record;
  const hybrid::HeldoutFreeRun reordered = run(std::numeric_limits<double>::infinity(), likely);
  EXPECT_EQ(reordered.error, whole.error);
  EXPECT_EQ(reordered.per_record, whole.per_record);

  const double bound = 0.5 * whole.error;
  const hybrid::HeldoutFreeRun in_order = run(bound, {});
  EXPECT_EQ(in_order.error, whole.error);  // the last record decides: all three run
  const hybrid::HeldoutFreeRun worst_first = run(bound, likely);
  EXPECT_GT(worst_first.error, bound);  // a lower bound, above what was asked
  EXPECT_LT(worst_first.error, whole.error);
  EXPECT_TRUE(std::isnan(worst_first.per_record[0]) && std::isnan(worst_first.per_record[1]));
  EXPECT_EQ(worst_first.per_record[2], whole.per_record[2]);
  // A guess the similar model left unrun (NaN) runs last.
  EXPECT_EQ(run(bound, {std::nan(""), std::nan(""), 1.0}).per_record[2], whole.per_record[2]);
  EXPECT_TRUE(std::isnan(run(bound, {std::nan(""), std::nan(""), 1.0}).per_record[0]));
}

TEST(HybridTest, RefusesWhatItCannotDo) {
  const Dataset data = Simulate({}, 60, 5);
  const std::vector<double>& start = FindVessel("odin3dof").Info().default_params;
  hybrid::HybridOptions options;
  options.heldout = 1.0;
  EXPECT_THROW(hybrid::IdentifyHybrid("odin3dof", data, start, options), InputError);
  options = {};
  options.max_terms = kMaxRefitTerms + 1;
  EXPECT_THROW(hybrid::IdentifyHybrid("odin3dof", data, start, options), InputError);
  options = {};
  options.search_rows = -1;
  EXPECT_THROW(hybrid::IdentifyHybrid("odin3dof", data, start, options), InputError);
  options = {};
  options.set_aside_cosine = 1.5;
  EXPECT_THROW(hybrid::IdentifyHybrid("odin3dof", data, start, options), InputError);
  options = {};
  EXPECT_THROW(
      hybrid::IdentifyHybrid("odin-hs", data, FindVessel("odin-hs").Info().default_params, options),
      InputError);
}

// A residual of r' that is 2 v r + 0.3 u exactly: FROLS proposes those two terms first, with
// their coefficients. (u varies about a small mean: FROLS is greedy, and a column close to the
// constant would be taken for it. The library is built from the residual's states, in their
// order, and the inputs.)
TEST(TermProposalsTest, FindsTheTermsOfAKnownResidual) {
  const Eigen::Index n = 400;
  Dataset d;
  Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(n, 0.0, 39.9);
  d.SetTime(t);
  const Eigen::VectorXd u = (0.2 + (0.21 * t.array()).sin()).matrix();
  const Eigen::VectorXd v = (0.5 * (0.37 * t.array()).cos()).matrix();
  const Eigen::VectorXd r = (0.2 * (0.53 * t.array() + 1.0).sin()).matrix();
  const Eigen::VectorXd delta = (0.1 * (0.11 * t.array()).sin()).matrix();
  d.Set("u", u);
  d.Set("v", v);
  d.Set("r", r);
  d.Set("delta", delta);
  std::map<std::string, Eigen::VectorXd> residual;
  residual["r"] = (2.0 * v.array() * r.array() + 0.3 * u.array()).matrix();
  residual["u"] = Eigen::VectorXd::Zero(n);  // nothing missing: no proposal
  residual["v"] = Eigen::VectorXd::Zero(n);
  const auto p = hybrid::ProposeTerms(d, residual, {"delta"}, 2);
  ASSERT_EQ(p.size(), 2u);
  std::map<std::string, double> found;
  for (const auto& q : p) {
    EXPECT_EQ(q.term.state, "r");
    found[q.term.term] = q.term.at("coefficient");
  }
  EXPECT_NEAR(found.at("r*v"), 2.0, 1e-9);
  EXPECT_NEAR(found.at("u"), 0.3, 1e-9);
  // Speed-scaled (MMG): U^2 f(v/u, r/u, delta), so a rudder term is u*u*delta.
  residual["r"] = (0.01 * u.array() * u.array() * delta.array()).matrix();
  const auto scaled = hybrid::ProposeTerms(d, residual, {"delta"}, 1, "u");
  ASSERT_EQ(scaled.size(), 1u);
  EXPECT_EQ(scaled[0].term.term, "u*u*delta");
  EXPECT_NEAR(scaled[0].term.at("coefficient"), 0.01, 1e-12);
}

// A term of a freed coefficient's own shape is that coefficient (free_coefficient_shape.h): on
// a KVLCC2 zig-zag, the MMG yaw moment of N_v is 1/2 rho L^2 d U^2 N_v v/U, so r' += c u v has
// its shape (|cos| above 0.99), and r' += c u r that of N_r; the cross-flow |v| v and the
// rudder's u^2 delta are the shape of no freed coefficient, nor is anything with none freed.
TEST(FreeCoefficientShapeTest, ATermOfAFreedCoefficientsShapeIsThatCoefficient) {
  const VesselSimulator& sim = FindVessel("kvlcc2");
  const VesselInfo& info = sim.Info();
  auto m = MakeManeuver("zigzag:20/20", info.actuation, 600, 1);
  const Dataset data = sim.RunManeuver(*m, info.default_params, {}, RunOptions{}).data;
  const std::vector<std::string> states = {"u", "v", "r"};
  const PreparedData prepared = Preprocess(data, states, info.InputsIn(data), PreprocessOptions{});
  auto term = [](const std::string& state, const std::string& expression) {
    return hybrid::TermProposal{
        Effect{EffectKind::kMissingTerm, {{"coefficient", 1.0}}, {}, state, expression}, 0.0};
  };
  const std::vector<hybrid::TermProposal> proposals = {
      term("r", "u*v"), term("r", "u*r"), term("r", "abs(v)*v"), term("r", "u*u*delta")};
  const auto shapes = hybrid::ClosestFreeCoefficient(
      "kvlcc2", prepared.data, info.params, info.default_params, {"N_v", "N_r"}, proposals);
  ASSERT_EQ(shapes.size(), 4u);
  EXPECT_EQ(shapes[0].parameter, "N_v");
  EXPECT_GT(shapes[0].cosine, 0.99);
  EXPECT_EQ(shapes[1].parameter, "N_r");
  EXPECT_GT(shapes[1].cosine, 0.99);
  EXPECT_LT(shapes[2].cosine, 0.99);
  EXPECT_LT(shapes[3].cosine, 0.99);
  // The hybrid, asked to, sets aside exactly the proposals of a freed coefficient's shape (here
  // the yaw moment r' += 2e-4 u v hidden in the data, N_v's), and tells every other its closest.
  const Effect sway_moment{EffectKind::kMissingTerm, {{"coefficient", 2e-4}}, {}, "r", "u*v"};
  const Dataset hidden =
      sim.RunManeuver(*m, info.default_params, ValuesOf({sway_moment}, info.inputs, info.states),
                      RunOptions{})
          .data;
  hybrid::HybridOptions options;
  options.max_terms = 0;
  options.set_aside_cosine = 0.99;
  const hybrid::HybridResult h =
      hybrid::IdentifyHybrid("kvlcc2", hidden, info.default_params, options);
  ASSERT_FALSE(h.set_aside.empty());
  for (const auto& [p, shape] : h.set_aside) EXPECT_GE(shape.cosine, 0.99) << p.term.term;
  ASSERT_EQ(h.proposal_shapes.size(), h.proposals.size());
  for (const auto& shape : h.proposal_shapes) EXPECT_LT(shape.cosine, 0.99) << shape.parameter;
  const auto none = hybrid::ClosestFreeCoefficient("kvlcc2", prepared.data, info.params,
                                                   info.default_params, {}, proposals);
  EXPECT_EQ(none[0].parameter, "");
  EXPECT_EQ(none[0].cosine, 0.0);
}

}  // namespace
}  // namespace usvid
