// The cubic smoothing spline: exact where it must be, the right limits, an honest noise estimate,
// derivatives far better than differencing noisy data, no lag, O(n).
#include "preprocessing/smoothing_spline.h"

#include <gtest/gtest.h>

#include <Eigen/QR>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>

#include "core/error.h"
#include "tests/support/test_signals.h"

namespace usvid {
namespace {

using testing::Signal;
using testing::Sines;

// x' = -0.5 x + u, u held 2-8 s at random levels: x' jumps whenever u does.
Signal StepResponse(int n, double dt, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> hold(2.0, 8.0);
  std::normal_distribution<double> level(0.0, 1.0);
  Signal s{Eigen::VectorXd(n), Eigen::VectorXd(n)};
  double t0 = 0.0, x0 = 0.0, u = level(rng), next = hold(rng);
  for (int i = 0; i < n; ++i) {
    const double t = i * dt;
    for (; t >= next; next += hold(rng)) {
      x0 = 2.0 * u + (x0 - 2.0 * u) * std::exp(-0.5 * (next - t0));
      t0 = next;
      u = level(rng);
    }
    s.x(i) = 2.0 * u + (x0 - 2.0 * u) * std::exp(-0.5 * (t - t0));
    s.dx(i) = -0.5 * s.x(i) + u;
  }
  return s;
}

double Sd(const Eigen::VectorXd& x) { return std::sqrt((x.array() - x.mean()).square().mean()); }
double Rms(const Eigen::VectorXd& e) { return std::sqrt(e.squaredNorm() / e.size()); }

Eigen::VectorXd AddNoise(const Eigen::VectorXd& x, double sd, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, sd);
  Eigen::VectorXd y = x;
  for (double& v : y) v += noise(rng);
  return y;
}

Eigen::VectorXd CentralDifference(const Eigen::VectorXd& y, double dt) {
  const Eigen::Index n = y.size();
  Eigen::VectorXd d(n);
  d(0) = (y(1) - y(0)) / dt;
  d(n - 1) = (y(n - 1) - y(n - 2)) / dt;
  d.segment(1, n - 2) = (y.tail(n - 2) - y.head(n - 2)) / (2.0 * dt);
  return d;
}

class SmoothingSplineTest : public ::testing::Test {};

// On a sum of sines with 1 % noise the automatic spline's derivative error is 1/29 of the central
// difference's (0.020 against 0.58, over all samples including the ends).
TEST_F(SmoothingSplineTest, RecoversDerivativeOfNoisySinesFarBetterThanFiniteDifference) {
  const double dt = 0.01;
  const Signal s = Sines(4000, dt);
  const Eigen::VectorXd y = AddNoise(s.x, 0.01 * Sd(s.x), 1);
  const SmoothingSplineResult r = SmoothingSpline(y, dt);
  const double spline = Rms(r.derivative - s.dx), difference = Rms(CentralDifference(y, dt) - s.dx);
  EXPECT_LT(spline, difference / 20.0) << spline << " vs " << difference;
  EXPECT_LT(spline, 0.03 * Sd(s.dx));
  EXPECT_LT(Rms(r.value - s.x), 0.01 * Sd(s.x) / 3.0);
}

// lambda -> 0 gives the interpolating natural spline, which reproduces a cubic exactly away from
// the ends (the natural end condition f'' = 0 disturbs it by a factor 2 - sqrt(3) less per knot
// inwards, below 1e-10 after 20 knots).
TEST_F(SmoothingSplineTest, DerivativeOfCubicIsExactForVanishingLambda) {
  const int n = 200;
  const double dt = 0.1;
  Eigen::VectorXd y(n), dy(n);
  for (int i = 0; i < n; ++i) {
    const double t = i * dt - 7.0;
    y(i) = 0.3 * t * t * t - 2.0 * t * t + t - 4.0;
    dy(i) = 0.9 * t * t - 4.0 * t + 1.0;
  }
  const SmoothingSplineResult r = SmoothingSpline(y, dt, 1e-12);
  const int m = n - 40;
  EXPECT_LT((r.derivative - dy).segment(20, m).cwiseAbs().maxCoeff(),
            1e-8 * dy.cwiseAbs().maxCoeff());
  EXPECT_LT((r.value - y).cwiseAbs().maxCoeff(), 1e-8 * y.cwiseAbs().maxCoeff());
}

// In the interior a sinusoid of w rad per sample comes out scaled by the smoother's exact response
// r / (r + mu d^2), r = (2 + cos w) / 3, d = 2 - 2 cos w; here mu = w^-4, so by about one half.
TEST_F(SmoothingSplineTest, MatchesExactFrequencyResponseInTheInterior) {
  const int n = 4000;
  const double dt = 0.1, w = 0.1, mu = std::pow(w, -4.0);
  Eigen::VectorXd y(n);
  for (int i = 0; i < n; ++i) y(i) = std::sin(w * i) + 5.0;
  const SmoothingSplineResult r = SmoothingSpline(y, dt, mu * dt * dt * dt);
  const double rr = (2.0 + std::cos(w)) / 3.0, d = 2.0 - 2.0 * std::cos(w);
  const double gain = rr / (rr + mu * d * d);
  EXPECT_NEAR(gain, 0.5, 0.01);
  for (int i = n / 4; i < 3 * n / 4; ++i)
    ASSERT_NEAR(r.value(i), 5.0 + gain * std::sin(w * i), 1e-10);
}

// lambda -> infinity leaves only what the penalty ignores: the least-squares straight line.
TEST_F(SmoothingSplineTest, LargeLambdaTendsToLeastSquaresLine) {
  const int n = 50;
  const double dt = 0.2;
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(n, 0.0, (n - 1) * dt);
  const Eigen::VectorXd x = (3.0 - 0.5 * t.array() + (2.0 * t.array()).sin()).matrix();
  const Eigen::VectorXd y = AddNoise(x, 0.3, 2);
  Eigen::MatrixXd a(n, 2);
  a << Eigen::VectorXd::Ones(n), t;
  const Eigen::Vector2d line = a.colPivHouseholderQr().solve(y);
  const SmoothingSplineResult r = SmoothingSpline(y, dt, 1e12 * dt * dt * dt);
  EXPECT_LT((r.value - a * line).cwiseAbs().maxCoeff(), 1e-4);
  EXPECT_LT((r.derivative.array() - line(1)).abs().maxCoeff(), 1e-4);
}

// Fourth differences of white noise on a smooth signal give its sd within 20 % from 0.1 % to 5 %.
TEST_F(SmoothingSplineTest, EstimatesNoiseSdOfWhiteNoiseOnSmoothSignal) {
  const double dt = 0.05;
  const Signal s = Sines(4000, dt);
  for (double level : {0.001, 0.01, 0.05}) {
    const double sd = level * Sd(s.x);
    const SmoothingSplineResult r = SmoothingSpline(AddNoise(s.x, sd, 3), dt);
    EXPECT_NEAR(r.noise_sd, sd, 0.2 * sd) << "noise level " << level;
  }
}

// Noise-free data: no noise is found, lambda is tiny and the spline interpolates; its derivative
// is accurate away from the ends, where the natural condition f'' = 0 does not hold for sines.
TEST_F(SmoothingSplineTest, ZeroNoiseGivesInterpolatingSpline) {
  const double dt = 0.05;
  const Signal s = Sines(2000, dt);
  const SmoothingSplineResult r = SmoothingSpline(s.x, dt);
  EXPECT_LT(r.noise_sd, 1e-4);
  EXPECT_LT(r.lambda / (dt * dt * dt), 1e-6);
  EXPECT_LT((r.value - s.x).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT(Rms((r.derivative - s.dx).segment(20, 2000 - 40)), 1e-5);
}

// Peak of the cross-correlation of `estimate` against `truth` over lags -10..10, refined by a
// parabola through the peak [samples; positive: the estimate is late].
double CorrelationPeakLag(const Eigen::VectorXd& estimate, const Eigen::VectorXd& truth) {
  const int max_lag = 10;
  const auto n = truth.size() - 2 * max_lag;
  Eigen::VectorXd corr(2 * max_lag + 1);
  for (int lag = -max_lag; lag <= max_lag; ++lag)
    corr(lag + max_lag) = estimate.segment(max_lag + lag, n).dot(truth.segment(max_lag, n));
  Eigen::Index peak = 0;
  corr.maxCoeff(&peak);
  if (peak == 0 || peak == 2 * max_lag) return static_cast<double>(peak - max_lag);
  const double a = corr(peak - 1), b = corr(peak), c = corr(peak + 1);
  return static_cast<double>(peak - max_lag) + 0.5 * (a - c) / (a - 2.0 * b + c);
}

// The smoother is symmetric, so its derivative has no lag: the cross-correlation with the true
// derivative peaks within 0.1 sample of 0 at 5 % noise, where a backward difference of the same
// spline's values (the check's own check) lags by half a sample.
TEST_F(SmoothingSplineTest, DerivativeHasNoLag) {
  const double dt = 0.05;
  const Signal s = StepResponse(6000, dt, 4);
  const SmoothingSplineResult r = SmoothingSpline(AddNoise(s.x, 0.05 * Sd(s.x), 5), dt);
  EXPECT_LT(std::abs(CorrelationPeakLag(r.derivative, s.dx)), 0.1);
  Eigen::VectorXd backward = r.derivative;
  backward.tail(5999) = (r.value.tail(5999) - r.value.head(5999)) / dt;
  EXPECT_NEAR(CorrelationPeakLag(backward, s.dx), 0.5, 0.1);
}

// Derivative jumps (piecewise-constant inputs): with 1 % noise the automatic lambda's derivative
// error is within 10 % of the best lambda's, and well below the central difference's.
TEST_F(SmoothingSplineTest, AutomaticLambdaNearBestWhenDerivativeJumps) {
  const double dt = 0.05;
  const Signal s = StepResponse(12001, dt, 6);
  const Eigen::VectorXd y = AddNoise(s.x, 0.01 * Sd(s.x), 7);
  const double automatic = Rms(SmoothingSpline(y, dt).derivative - s.dx);
  double best = std::numeric_limits<double>::infinity();
  for (double mu = 1e-2; mu < 1e4; mu *= 1.5)
    best = std::min(best, Rms(SmoothingSpline(y, dt, mu * dt * dt * dt).derivative - s.dx));
  EXPECT_LT(automatic, 1.1 * best);
  EXPECT_LT(automatic, 0.6 * Rms(CentralDifference(y, dt) - s.dx));
}

// Bad input throws InputError naming the fault.
TEST_F(SmoothingSplineTest, ThrowsOnBadInput) {
  const Eigen::VectorXd y = Eigen::VectorXd::LinSpaced(10, 0.0, 1.0);
  auto message = [](auto&& call) {
    try {
      call();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no InputError");
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_NE(message([&] { SmoothingSpline(y, 0.0); }).find("dt"), std::string::npos);
  EXPECT_NE(message([&] { SmoothingSpline(y, -0.1); }).find("dt"), std::string::npos);
  EXPECT_NE(message([&] { SmoothingSpline(y, nan); }).find("dt"), std::string::npos);
  EXPECT_NE(message([&] { SmoothingSpline(y.head(3), 0.1); }).find("at least 4"),
            std::string::npos);
  Eigen::VectorXd bad = y;
  bad(7) = nan;
  EXPECT_NE(message([&] { SmoothingSpline(bad, 0.1); }).find("sample 7"), std::string::npos);
  bad(7) = -inf;
  EXPECT_NE(message([&] { SmoothingSpline(bad, 0.1); }).find("sample 7"), std::string::npos);
  EXPECT_NE(message([&] { SmoothingSpline(y, 0.1, nan); }).find("lambda"), std::string::npos);
  EXPECT_NE(message([&] { SmoothingSpline(y, 0.1, inf); }).find("lambda"), std::string::npos);
  EXPECT_NO_THROW(SmoothingSpline(y.head(4), 0.1));
}

// 100 000 samples with automatic lambda: O(n), so a fraction of a second (printed, not asserted).
TEST_F(SmoothingSplineTest, HandlesOneHundredThousandSamples) {
  const double dt = 0.01;
  const Signal s = Sines(100000, dt);
  const Eigen::VectorXd y = AddNoise(s.x, 0.01 * Sd(s.x), 8);
  const auto start = std::chrono::steady_clock::now();
  const SmoothingSplineResult r = SmoothingSpline(y, dt);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  std::printf("SmoothingSpline, n = 100000, automatic lambda: %.1f ms\n", 1e3 * elapsed.count());
  EXPECT_LT(Rms(r.derivative - s.dx), 0.03 * Sd(s.dx));
}

}  // namespace
}  // namespace usvid
