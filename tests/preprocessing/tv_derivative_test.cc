// Total-variation differentiation: sharp jumps kept, smooth derivatives recovered, no lag, no
// dependence on units, O(n), bad input refused.
#include "preprocessing/tv_derivative.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/error.h"
#include "tests/support/test_signals.h"

namespace usvid {
namespace {

using testing::Signal;
using testing::Sines;

// Slopes held between kinks that fall between samples: the derivative is piecewise constant, with
// jumps of 2 to 4.
const std::vector<double> kKinks = {1.234, 2.717, 3.905, 5.551, 6.808, 8.2};

Signal PiecewiseLinear(int n, double dt) {
  const std::vector<double> slopes = {1.0, -2.0, 0.5, 3.0, -1.0, 1.5, -0.5};
  Signal s{Eigen::VectorXd(n), Eigen::VectorXd(n)};
  double x = 5.0, t_prev = 0.0;
  size_t k = 0;
  for (int i = 0; i < n; ++i) {
    const double t = i * dt;
    while (k < kKinks.size() && kKinks[k] <= t) {
      x += slopes[k] * (kKinks[k] - t_prev);
      t_prev = kKinks[k++];
    }
    s.x(i) = x + slopes[k] * (t - t_prev);
    s.dx(i) = slopes[k];
  }
  return s;
}

// x' = -0.5 x + u, u held 2-8 s at random levels (exact between switches): x' jumps with u.
Signal StepResponse(int n, double dt, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> hold(2.0, 8.0), level(-1.0, 1.0);
  Signal s{Eigen::VectorXd(n), Eigen::VectorXd(n)};
  double t0 = 0.0, x0 = 0.0, u = level(rng), next = hold(rng);
  for (int i = 0; i < n; ++i) {
    const double t = i * dt;
    while (next <= t) {
      x0 = 2.0 * u + (x0 - 2.0 * u) * std::exp(-0.5 * (next - t0));
      t0 = next;
      u = level(rng);
      next += hold(rng);
    }
    s.x(i) = 2.0 * u + (x0 - 2.0 * u) * std::exp(-0.5 * (t - t0));
    s.dx(i) = -0.5 * s.x(i) + u;
  }
  return s;
}

// 30 sines of random frequency (0.02 to 1.5 Hz), amplitude and phase.
Signal RandomSines(int n, double dt, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> frequency(0.02, 1.5), phase(0.0, 6.283185307179586);
  std::normal_distribution<double> amplitude(0.0, 1.0);
  Signal s{Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
  for (int k = 0; k < 30; ++k) {
    const double w = 6.283185307179586 * frequency(rng), a = amplitude(rng) / w, p = phase(rng);
    for (int i = 0; i < n; ++i) {
      s.x(i) += a * std::sin(w * i * dt + p);
      s.dx(i) += a * w * std::cos(w * i * dt + p);
    }
  }
  return s;
}

double Sd(const Eigen::VectorXd& v) { return std::sqrt((v.array() - v.mean()).square().mean()); }
double Rms(const Eigen::VectorXd& v) { return std::sqrt(v.array().square().mean()); }

Eigen::VectorXd AddNoise(const Eigen::VectorXd& x, double sd, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, sd);
  Eigen::VectorXd y = x;
  for (Eigen::Index i = 0; i < y.size(); ++i) y(i) += noise(rng);
  return y;
}

Eigen::VectorXd CentralDifference(const Eigen::VectorXd& y, double dt) {
  const Eigen::Index n = y.size();
  Eigen::VectorXd d(n);
  d.segment(1, n - 2) = (y.tail(n - 2) - y.head(n - 2)) / (2.0 * dt);
  d(0) = (y(1) - y(0)) / dt;
  d(n - 1) = (y(n - 1) - y(n - 2)) / dt;
  return d;
}

// The lag (in samples, interpolated) at which the cross-correlation of a with b peaks.
double PeakLag(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const Eigen::Index n = a.size(), m = 5;
  const Eigen::VectorXd x = a.array() - a.mean(), y = b.array() - b.mean();
  std::vector<double> c(2 * m + 1);
  for (Eigen::Index lag = -m; lag <= m; ++lag)
    c[lag + m] = x.segment(m + lag, n - 2 * m).dot(y.segment(m, n - 2 * m));
  Eigen::Index k = 1;
  for (Eigen::Index i = 1; i < 2 * m; ++i)
    if (c[i] > c[k]) k = i;
  const double curvature = c[k - 1] - 2.0 * c[k] + c[k + 1];
  return static_cast<double>(k - m) + 0.5 * (c[k - 1] - c[k + 1]) / curvature;
}

class TvDerivativeTest : public ::testing::Test {};

// Kinks between samples, 1 % noise: each jump of the slope comes back centred on its kink (within
// 2 samples) and sharp (10 % to 90 % within 20 samples, typically 5), the RMS error about 10 times
// below that of a central difference of the noisy data.
TEST_F(TvDerivativeTest, PiecewiseLinearSignalKeepsSharpJumps) {
  const double dt = 0.01;
  const Signal s = PiecewiseLinear(1001, dt);
  const Eigen::VectorXd y = AddNoise(s.x, 0.01 * Sd(s.x), 1);
  const TvDerivativeResult r = TvDerivative(y, dt);
  const double tv = Rms(r.derivative - s.dx), central = Rms(CentralDifference(y, dt) - s.dx);
  std::printf("piecewise linear, 1 %% noise: RMS error %.3f, central difference %.3f (%.1fx)\n", tv,
              central, central / tv);
  EXPECT_GT(central / tv, 8.0);
  std::vector<double> widths;
  for (const double kink : kKinks) {
    // Where (in samples, interpolated) the estimate has moved a fraction of the way across.
    const Eigen::Index k = static_cast<Eigen::Index>(std::ceil(kink / dt));
    const double before = s.dx(k - 1), jump = s.dx(k) - before;
    auto crossed = [&](double fraction) {
      Eigen::Index i = k - 20;
      while (i < k + 20 && (r.derivative(i) - before) / jump < fraction) ++i;
      const double a = (r.derivative(i - 1) - before) / jump, b = (r.derivative(i) - before) / jump;
      return static_cast<double>(i - 1) + (fraction - a) / (b - a);
    };
    widths.push_back(crossed(0.9) - crossed(0.1));
    EXPECT_LT(widths.back(), 20.0) << "kink at t = " << kink;
    EXPECT_NEAR(crossed(0.5), kink / dt, 2.0) << "kink at t = " << kink;
  }
  std::sort(widths.begin(), widths.end());
  EXPECT_LT(0.5 * (widths[2] + widths[3]), 8.0);
}

// Three sines, 1 % noise: TV with the automatic weight still follows a smooth derivative, and
// its fitted signal is closer to the truth than the data.
TEST_F(TvDerivativeTest, SmoothSignalDerivativeRecovered) {
  const double dt = 0.01;
  const Signal s = Sines(2001, dt);
  const Eigen::VectorXd y = AddNoise(s.x, 0.01 * Sd(s.x), 2);
  const TvDerivativeResult r = TvDerivative(y, dt);
  EXPECT_LT(Rms(r.derivative - s.dx), 0.06 * Sd(s.dx));  // 0.04 typical: TV staircases a little
  EXPECT_LT(Rms(r.value - s.x), 0.005 * Sd(s.x));
}

// Broadband signal at 20 Hz, 1 % noise: the cross-correlation of the estimate with the true
// derivative peaks at lag 0 to within 0.05 sample; the backward difference shows its half sample.
TEST_F(TvDerivativeTest, ZeroPhase) {
  const double dt = 0.05;
  const Signal s = RandomSines(4001, dt, 3);
  const Eigen::VectorXd y = AddNoise(s.x, 0.01 * Sd(s.x), 3);
  const TvDerivativeResult r = TvDerivative(y, dt);
  EXPECT_NEAR(PeakLag(r.derivative, s.dx), 0.0, 0.05);
  Eigen::VectorXd backward(y.size());
  backward(0) = (y(1) - y(0)) / dt;
  backward.tail(y.size() - 1) = (y.tail(y.size() - 1) - y.head(y.size() - 1)) / dt;
  EXPECT_NEAR(PeakLag(backward, s.dx), 0.5, 0.05);
}

// Zero phase exactly: reversing the record in time reverses and negates the derivative, so the
// estimate can lag neither way (a signal with jumps, where bias could otherwise hide a lag).
TEST_F(TvDerivativeTest, TimeReversalNegatesDerivative) {
  const double dt = 0.05;
  const Signal s = StepResponse(3001, dt, 7);
  const Eigen::VectorXd y = AddNoise(s.x, 0.01 * Sd(s.x), 7);
  const TvDerivativeResult forward = TvDerivative(y, dt);
  const TvDerivativeResult backward = TvDerivative(y.reverse(), dt);
  EXPECT_LT((backward.derivative.reverse() + forward.derivative).cwiseAbs().maxCoeff(),
            1e-8 * forward.derivative.cwiseAbs().maxCoeff());
  EXPECT_DOUBLE_EQ(backward.alpha, forward.alpha);
}

// With the automatic weight the result does not depend on units: f * 1000 gives 1000 times the
// derivative and alpha, an offset changes nothing, and the time step only divides.
TEST_F(TvDerivativeTest, ResultDoesNotDependOnUnits) {
  const double dt = 0.05;
  const Signal s = StepResponse(2001, dt, 4);
  const Eigen::VectorXd y = AddNoise(s.x, 0.02 * Sd(s.x), 4);
  const TvDerivativeResult r = TvDerivative(y, dt);
  const double tol = 1e-9 * r.derivative.cwiseAbs().maxCoeff();
  const TvDerivativeResult scaled = TvDerivative(1000.0 * y, dt);
  EXPECT_LT((scaled.derivative / 1000.0 - r.derivative).cwiseAbs().maxCoeff(), tol);
  EXPECT_NEAR(scaled.alpha / r.alpha, 1000.0, 1e-6);
  const TvDerivativeResult shifted = TvDerivative(y.array() + 250.0, dt);
  EXPECT_LT((shifted.derivative - r.derivative).cwiseAbs().maxCoeff(), 1e-6);
  const TvDerivativeResult slow = TvDerivative(y, 1.0);
  EXPECT_LT((slow.derivative / dt - r.derivative).cwiseAbs().maxCoeff(), tol);
}

// Passing back the alpha that was chosen reproduces the automatic result.
TEST_F(TvDerivativeTest, ChosenAlphaReproducesResult) {
  const double dt = 0.05;
  const Signal s = StepResponse(2001, dt, 5);
  const Eigen::VectorXd y = AddNoise(s.x, 0.01 * Sd(s.x), 5);
  const TvDerivativeResult automatic = TvDerivative(y, dt);
  TvDerivativeOptions options;
  options.alpha = automatic.alpha;
  const TvDerivativeResult fixed = TvDerivative(y, dt, options);
  EXPECT_LT((fixed.derivative - automatic.derivative).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_EQ(fixed.iterations, automatic.iterations);
}

// A straight line costs no total variation: its slope comes back exactly, noise-free (alpha 0) or
// with any weight, and a constant has zero derivative.
TEST_F(TvDerivativeTest, StraightLineSlopeIsExact) {
  const Eigen::VectorXd line = Eigen::VectorXd::LinSpaced(50, -3.0, 4.0 * 49 * 0.1 - 3.0);
  const TvDerivativeResult r = TvDerivative(line, 0.1);
  EXPECT_EQ(r.alpha, 0.0);
  EXPECT_LT((r.derivative.array() - 4.0).abs().maxCoeff(), 1e-9);
  TvDerivativeOptions options;
  options.alpha = 10.0;
  EXPECT_LT((TvDerivative(line, 0.1, options).derivative.array() - 4.0).abs().maxCoeff(), 1e-6);
  EXPECT_EQ(TvDerivative(Eigen::VectorXd::Constant(4, 2.5), 0.1).derivative.cwiseAbs().maxCoeff(),
            0.0);
}

// 100 000 samples with the automatic weight: O(n), well under a second in Release (printed).
TEST_F(TvDerivativeTest, HandlesOneHundredThousandSamples) {
  const double dt = 0.05;
  const Signal s = StepResponse(100001, dt, 6);
  const Eigen::VectorXd y = AddNoise(s.x, 0.01 * Sd(s.x), 6);
  const auto start = std::chrono::steady_clock::now();
  const TvDerivativeResult r = TvDerivative(y, dt);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  std::printf("TvDerivative, n = 100001, automatic alpha: %.0f ms\n", 1e3 * elapsed.count());
  EXPECT_LT(Rms(r.derivative - s.dx), 0.2 * Sd(s.dx));
}

// Bad input is refused with a message naming what is wrong.
TEST_F(TvDerivativeTest, BadInputThrows) {
  auto message = [](const std::function<void()>& call) -> std::string {
    try {
      call();
    } catch (const InputError& e) {
      return e.what();
    }
    return "no InputError";
  };
  auto names = [&](const std::function<void()>& call, const std::string& what) {
    const std::string m = message(call);
    EXPECT_NE(m.find(what), std::string::npos) << m;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Eigen::VectorXd y = Eigen::VectorXd::LinSpaced(10, 0.0, 1.0);
  names([&] { TvDerivative(y, 0.0); }, "dt");
  names([&] { TvDerivative(y, -0.1); }, "dt");
  names([&] { TvDerivative(y, nan); }, "dt");
  names([&] { TvDerivative(y.head(3), 0.1); }, "at least 4 samples");
  Eigen::VectorXd bad = y;
  bad(7) = nan;
  names([&] { TvDerivative(bad, 0.1); }, "sample 7");
  bad(7) = -inf;
  names([&] { TvDerivative(bad, 0.1); }, "sample 7");
  TvDerivativeOptions options;
  options.iterations = 0;
  names([&] { TvDerivative(y, 0.1, options); }, "iterations");
  options = {};
  options.epsilon = 0.0;
  names([&] { TvDerivative(y, 0.1, options); }, "epsilon");
  options = {};
  options.alpha = nan;
  names([&] { TvDerivative(y, 0.1, options); }, "alpha");
  EXPECT_NO_THROW(TvDerivative(y.head(4), 0.1));
}

}  // namespace
}  // namespace usvid
