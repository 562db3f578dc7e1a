// Derivative estimates on odin3dof data with 1 % noise (issue 4): the error of u', v', r'
// against the true derivatives (the model's right-hand side at the clean states), relative to
// the reference report's pipeline (Savitzky-Golay smoothing over 11 samples, then its eq. 4.9,
// forward Euler differences), and the lag (cross-correlation peak) against the truth.
//  - Smooth inputs (multisine): the default estimator is at least 5 times more accurate, with
//    less than one sample of lag.
//  - Piecewise-constant inputs (random steps): the true derivative jumps at every step. Told the
//    steps (StepBreaks), the default fits each stretch between them on its own: at least twice
//    as accurate as the report's pipeline and with a tenth of a sample of lag; the stretches are
//    short (about 3 s), which bounds the gain (docs/preprocessing.md has the whole table).
//  - The whole pipeline on a KVLCC2 zig-zag whose propeller is held: r' is the true one.
#include <gtest/gtest.h>

#include "maneuvers/maneuver_factory.h"
#include "metrics/fit_metrics.h"
#include "preprocessing/cross_correlation.h"
#include "preprocessing/derivative.h"
#include "preprocessing/pipeline.h"
#include "sensors/noise.h"
#include "simulation/vessel_simulator.h"
#include "simulators/odin3dof.h"

namespace usvid {
namespace {

class DerivativeAccuracyTest : public ::testing::Test {
 protected:
  struct Case {
    Dataset clean;
    Eigen::MatrixXd truth;
    std::vector<Eigen::Index> breaks;
  };

  static Case Make(const std::string& maneuver) {
    Case c;
    const VesselSimulator& sim = FindVessel("odin3dof");
    auto m = MakeManeuver(maneuver, sim.Info().actuation, 600.0, 21);
    c.clean = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
    c.truth.resize(c.clean.rows(), 3);
    for (Eigen::Index k = 0; k < c.clean.rows(); ++k) {
      double x[6], u[3], dx[6];
      int i = 0;
      for (const char* s : {"north", "east", "psi", "u", "v", "r"}) x[i++] = c.clean[s](k);
      i = 0;
      for (const char* s : {"tau_x", "tau_y", "tau_n"}) u[i++] = c.clean[s](k);
      Odin3Dof::Derivative<double>(x, u, Odin3Dof::kDefaultParams.data(), {}, dx);
      c.truth.row(k) << dx[3], dx[4], dx[5];
    }
    c.breaks = StepBreaks({c.clean["tau_x"], c.clean["tau_y"], c.clean["tau_n"]});
    return c;
  }

  struct Score {
    double rms = 0.0;      // mean over u, v, r of RMS error / RMS of the true derivative
    double max_lag = 0.0;  // largest |lag| in samples over u, v, r
  };

  static Score Evaluate(const Case& c, const std::string& spec, double noise, bool breaks) {
    Dataset noisy = c.clean;
    AddGaussianNoise(noisy, {"u", "v", "r"}, noise, 77);
    const DerivativeMethod method = DerivativeMethod::Parse(spec);
    const std::vector<Eigen::Index> none;
    Score s;
    int col = 0;
    for (const char* name : {"u", "v", "r"}) {
      const Eigen::VectorXd d =
          SmoothAndDifferentiate(noisy[name], 0.05, method, breaks ? c.breaks : none).derivative;
      const Eigen::VectorXd truth = c.truth.col(col++);
      s.rms += std::sqrt((d - truth).squaredNorm() / truth.squaredNorm()) / 3.0;
      s.max_lag = std::max(s.max_lag, std::abs(EstimateLag(truth, d, 20).lag));
    }
    return s;
  }
};

TEST_F(DerivativeAccuracyTest, SmoothInputsDefaultIsFiveTimesBetterWithoutLag) {
  const Case c = Make("multisine");
  const Score report = Evaluate(c, "euler", 0.01, false);
  const Score best = Evaluate(c, DerivativeMethod{}.Spec(), 0.01, true);
  EXPECT_LE(best.rms * 5.0, report.rms) << "default " << best.rms << ", report " << report.rms;
  EXPECT_LT(best.max_lag, 1.0);
}

TEST_F(DerivativeAccuracyTest, StepInputsWithBreaksTwiceBetterAndAligned) {
  const Case c = Make("random-steps");
  EXPECT_GT(c.breaks.size(), 100u);
  const Score report = Evaluate(c, "euler", 0.01, false);
  const Score plain = Evaluate(c, DerivativeMethod{}.Spec(), 0.01, false);
  const Score best = Evaluate(c, DerivativeMethod{}.Spec(), 0.01, true);
  EXPECT_LE(best.rms * 2.0, report.rms) << "default " << best.rms << ", report " << report.rms;
  EXPECT_LT(best.rms, plain.rms * 0.75);  // the breaks matter
  EXPECT_LT(best.max_lag, 0.25);
}

// Every estimator stays usable over the noise range of the docs table (0.1 % to 5 %): its
// error grows with the noise and stays below the signal, and the centred ones keep within a
// sample of the truth.
TEST_F(DerivativeAccuracyTest, EstimatorsDegradeGracefullyWithNoise) {
  const Case c = Make("multisine");
  for (const std::string spec : {"sg:21:3", "spline", "tv"}) {
    const Score low = Evaluate(c, spec, 0.001, false), high = Evaluate(c, spec, 0.05, false);
    EXPECT_LT(low.rms, high.rms) << spec;
    EXPECT_LT(high.rms, 0.5) << spec;
    EXPECT_LT(low.max_lag, 1.0) << spec;
  }
}

// The whole pipeline (resampling, breaks, spline) on a KVLCC2 zig-zag with 0.5 % noise, whose
// propeller is held at 91.7 rpm: r' against the central difference of the noise-free record.
// Resampling gave the held rpm back off by rounding, each rounding was taken for a step, and the
// breaks left r' with R^2 0.04 here; an input held constant has no steps (issue 38).
TEST(PipelineDerivativeTest, AZigzagUnderAHeldPropellerIsDifferentiatedWhole) {
  const VesselSimulator& sim = FindVessel("kvlcc2");
  auto m = MakeManeuver("zigzag:-20/20", sim.Info().actuation, 600.0, 3);
  const Dataset clean = sim.RunManeuver(*m, sim.Info().default_params, {}, RunOptions{}).data;
  Dataset noisy = clean;
  AddGaussianNoise(noisy, {"u", "v", "r"}, 0.005, 3);
  const PreparedData p = Preprocess(noisy, {"u", "v", "r"}, {"delta", "rev"}, {});
  const Eigen::VectorXd& t = clean.t();
  const Eigen::VectorXd& r = clean["r"];
  const Eigen::VectorXd& estimate = p.data["r_dot"];
  ASSERT_EQ(estimate.size(), r.size());
  const Eigen::Index n = r.size();
  Eigen::VectorXd truth(n - 2);
  for (Eigen::Index k = 1; k + 1 < n; ++k)
    truth(k - 1) = (r(k + 1) - r(k - 1)) / (t(k + 1) - t(k - 1));
  EXPECT_GT(RSquared(truth, estimate.segment(1, n - 2)), 0.99);
}

}  // namespace
}  // namespace usvid
