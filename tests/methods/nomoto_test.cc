// nomoto, the first-order Nomoto heading model T r' + r = K (delta - delta0)
// (methods/nomoto/nomoto.h): recovery of K, T and the neutral-rudder offset delta0 from a
// zig-zag-like square-wave rudder with noise on r, equations that parse and evaluate to the
// model, and bad input.
#include "methods/nomoto/nomoto.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "core/dataset.h"
#include "core/error.h"
#include "core/expression.h"
#include "preprocessing/pipeline.h"

namespace usvid {
namespace {

using nomoto::FitNomoto;
using nomoto::NomotoEquations;
using nomoto::NomotoFit;

constexpr double kK = 0.1;        // [1/s per rad]
constexpr double kT = 8.0;        // [s]
constexpr double kDelta0 = 0.01;  // [rad]

// 400 s at 2 Hz of the Nomoto model from rest, delta = +-0.35 rad switching every 40 s (held
// over each sample interval, integrated exactly), with Gaussian noise of 1 % of sd(r) on r.
Dataset NomotoRun() {
  constexpr int kRows = 801;
  constexpr double kDt = 0.5;
  Eigen::VectorXd t(kRows), r(kRows), delta(kRows);
  double rate = 0.0;
  for (int k = 0; k < kRows; ++k) {
    t(k) = k * kDt;
    delta(k) = static_cast<int>(t(k) / 40.0) % 2 == 0 ? 0.35 : -0.35;
    r(k) = rate;
    const double steady = kK * (delta(k) - kDelta0);
    rate = steady + (rate - steady) * std::exp(-kDt / kT);
  }
  const double sd = std::sqrt((r.array() - r.mean()).square().mean());
  std::mt19937_64 rng(20240611);
  std::normal_distribution<double> noise(0.0, 0.01 * sd);
  for (int k = 0; k < kRows; ++k) r(k) += noise(rng);
  Dataset d(t);
  d.Set("r", r);
  d.Set("delta", delta);
  return d;
}

TEST(NomotoTest, RecoversGainTimeConstantAndOffsetFromSquareWaveRudder) {
  const PreparedData prepared = Preprocess(NomotoRun(), {"r"}, {"delta"}, PreprocessOptions{});
  const NomotoFit fit = FitNomoto(prepared, "r", "delta", 30.0);
  std::cout << "equation error: K " << fit.equation_error_K << " T " << fit.equation_error_T
            << " delta0 " << fit.equation_error_delta0 << "\noutput error: K " << fit.K << " +- "
            << fit.sd_K << ", T " << fit.T << " +- " << fit.sd_T << ", delta0 " << fit.delta0
            << " +- " << fit.sd_delta0 << " (" << fit.termination << ", " << fit.seconds << " s)\n";
  for (const std::string& note : fit.notes) std::cout << "  " << note << "\n";
  EXPECT_TRUE(fit.converged) << fit.termination;
  EXPECT_NEAR(fit.K, kK, 0.05 * kK);
  EXPECT_NEAR(fit.T, kT, 0.05 * kT);
  EXPECT_NEAR(fit.delta0, kDelta0, 0.002);
  EXPECT_GT(fit.sd_K, 0.0);
  EXPECT_GT(fit.sd_T, 0.0);
  EXPECT_GT(fit.sd_delta0, 0.0);
}

TEST(NomotoTest, EquationsParseAndEvaluateToTheModel) {
  NomotoFit fit;
  fit.K = 0.0731;
  fit.T = 12.5;
  fit.delta0 = -0.0042;  // a negative offset prints as "delta - -0.0042"
  const nlohmann::json eq = NomotoEquations(fit, "r", "nozzle");
  ASSERT_TRUE(eq.contains("r"));
  ASSERT_EQ(eq.size(), 1u);
  const Expression e = Expression::Parse(eq["r"].get<std::string>());
  ASSERT_EQ(e.Variables(), (std::vector<std::string>{"nozzle", "r"}));
  const double nozzle = 0.21, r = -0.013;
  const std::vector<double> values = {nozzle, r};
  EXPECT_NEAR(e.Evaluate(values), (fit.K * (nozzle - fit.delta0) - r) / fit.T, 1e-15);
}

TEST(NomotoTest, MissingRateChannelIsAnInputError) {
  const PreparedData prepared = Preprocess(NomotoRun(), {"r"}, {"delta"}, PreprocessOptions{});
  EXPECT_THROW(FitNomoto(prepared, "yaw_rate", "delta", 30.0), InputError);
  EXPECT_THROW(FitNomoto(prepared, "r", "rudder", 30.0), InputError);
  EXPECT_THROW(FitNomoto(prepared, "r", "delta", 0.0), InputError);
}

}  // namespace
}  // namespace usvid
