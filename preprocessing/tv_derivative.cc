#include "preprocessing/tv_derivative.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/median.h"

namespace usvid {
namespace {

constexpr int kNoiseDifferenceOrder = 4;
constexpr double kStepTolerance = 1e-10;        // on max |w_k+1 - w_k| [std(f)]
constexpr double kLogLambdaMin = -8.0;
constexpr double kLogLambdaMax = 8.0;
constexpr double kLogLambdaStart = 0.0;
constexpr double kSearchResolution = 0.125;  // decades
constexpr double kNoiseFloor = 1e-9;         // [std(f)]: below, rounding, not noise

// H = I + lambda D2^T diag(q) D2 (D2: second differences), q given padded as qp(j + 2) = q_j
// with qp(0) = qp(1) = qp(n) = qp(n + 1) = 0. Factored as L diag(d) L^T; L has two subdiagonals.
class PentadiagonalLdlt {
 public:
  explicit PentadiagonalLdlt(Eigen::Index n) : d_(n), l1_(n), l2_(n) {}

  void Factor(double lambda, const Eigen::VectorXd& qp) {
    const Eigen::Index n = d_.size();
    for (Eigen::Index i = 0; i < n; ++i) {
      const double h0 = 1.0 + lambda * (qp(i) + 4.0 * qp(i + 1) + qp(i + 2));
      const double h1 = -2.0 * lambda * (qp(i) + qp(i + 1));  // H(i, i - 1)
      const double h2 = lambda * qp(i);                       // H(i, i - 2)
      const double l2 = i >= 2 ? h2 / d_(i - 2) : 0.0;
      const double l1 = i >= 2 ? (h1 - h2 * l1_(i - 1)) / d_(i - 1) : (i == 1 ? h1 / d_(0) : 0.0);
      double d = h0;
      if (i >= 1) d -= l1 * l1 * d_(i - 1);
      if (i >= 2) d -= l2 * l2 * d_(i - 2);
      d_(i) = d;
      l1_(i) = l1;
      l2_(i) = l2;
    }
  }

  void Solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
    const Eigen::Index n = d_.size();
    x = b;
    x(1) -= l1_(1) * x(0);
    for (Eigen::Index i = 2; i < n; ++i) x(i) -= l1_(i) * x(i - 1) + l2_(i) * x(i - 2);
    x.array() /= d_.array();
    x(n - 2) -= l1_(n - 1) * x(n - 1);
    for (Eigen::Index i = n - 3; i >= 0; --i) x(i) -= l1_(i + 1) * x(i + 1) + l2_(i + 2) * x(i + 2);
  }

  // trace(H^-1) from the band of Z = H^-1: Z = diag(d)^-1 L^-1 + (I - L^T) Z, bottom up.
  double TraceOfInverse() const {
    double z11 = 0.0, z12 = 0.0, z22 = 0.0, trace = 0.0;  // Z(i+1,i+1), Z(i+1,i+2), Z(i+2,i+2)
    for (Eigen::Index i = d_.size() - 1; i >= 0; --i) {
      const double a = i + 1 < d_.size() ? l1_(i + 1) : 0.0;
      const double b = i + 2 < d_.size() ? l2_(i + 2) : 0.0;
      const double z02 = -(a * z12 + b * z22);
      const double z01 = -(a * z11 + b * z12);
      const double z00 = 1.0 / d_(i) - (a * z01 + b * z02);
      trace += z00;
      z22 = z11;
      z12 = z01;
      z11 = z00;
    }
    return trace;
  }

 private:
  Eigen::VectorXd d_, l1_, l2_;
};

// The dimensionless problem: g = (f - mean f) / s on a unit grid; w fits g, jumps = D2 w.
class TvFitter {
 public:
  TvFitter(const Eigen::VectorXd& g, double epsilon)
      : g_(g),
        epsilon_(epsilon),
        ldlt_(g.size()),
        w_(g.size()),
        next_(g.size()),
        jump0_(g.size() + 2),
        jump_(g.size() + 2),
        qp_(g.size() + 2) {
    const Eigen::Index n = g.size();
    Eigen::VectorXd c(n);  // central difference of g
    c(0) = g(1) - g(0);
    c(n - 1) = g(n - 1) - g(n - 2);
    c.segment(1, n - 2) = 0.5 * (g.tail(n - 2) - g.head(n - 2));
    jump0_.setZero();
    jump0_.segment(2, n - 2) = 0.5 * (c.tail(n - 2) - c.head(n - 2));
    qp_.setZero();
  }

  // Lagged diffusivity w <- (I + lambda D2^T Q(w) D2)^-1 g, from the central-difference jumps.
  int Fit(double lambda, int iterations) {
    const Eigen::Index n = g_.size();
    jump_ = jump0_;
    w_ = g_;
    int k = 0;
    while (k < iterations) {
      qp_.segment(2, n - 2) = (jump_.segment(2, n - 2).array().square() + epsilon_).rsqrt();
      ldlt_.Factor(lambda, qp_);
      ldlt_.Solve(g_, next_);
      ++k;
      const double step = (next_ - w_).cwiseAbs().maxCoeff();
      w_.swap(next_);
      jump_.segment(2, n - 2) = w_.tail(n - 2) - 2.0 * w_.segment(1, n - 2) + w_.head(n - 2);
      if (step < kStepTolerance) break;
    }
    return k;
  }

  // Stein's unbiased risk estimate of w: |w - g|^2 + 2 sigma^2 df, df = trace of the inverse
  // Hessian of the smoothed functional (curvature epsilon / (x^2 + epsilon)^1.5 of each jump).
  double Sure(double lambda, double sigma) {
    const Eigen::Index n = g_.size();
    qp_.segment(2, n - 2) =
        epsilon_ * (jump_.segment(2, n - 2).array().square() + epsilon_).pow(-1.5);
    ldlt_.Factor(lambda, qp_);
    return (w_ - g_).squaredNorm() + 2.0 * sigma * sigma * ldlt_.TraceOfInverse();
  }

  const Eigen::VectorXd& w() const { return w_; }

 private:
  const Eigen::VectorXd& g_;
  double epsilon_;
  PentadiagonalLdlt ldlt_;
  Eigen::VectorXd w_, next_, jump0_, jump_, qp_;
};

// Robust noise sd of g: MAD of its k-th differences, whose variance is C(2k, k) sigma^2.
double NoiseSd(const Eigen::VectorXd& g) {
  const int order = static_cast<int>(std::min<Eigen::Index>(kNoiseDifferenceOrder, g.size() - 1));
  Eigen::VectorXd d = g;
  double variance_gain = 1.0;
  for (int k = 0; k < order; ++k) {
    d = (d.tail(d.size() - 1) - d.head(d.size() - 1)).eval();
    variance_gain = variance_gain * (2 * order - k) / (k + 1);
  }
  std::vector<double> a(d.data(), d.data() + d.size());
  for (double& x : a) x = std::abs(x);
  std::nth_element(a.begin(), a.begin() + a.size() / 2, a.end());
  const double mad = a[a.size() / 2];
  if (mad > 0.0) return kMadToSd * mad / std::sqrt(variance_gain);
  return std::sqrt(d.squaredNorm() / d.size() / variance_gain);  // mostly repeated values
}

// The lambda of least SURE: a decade walk from the start while the risk falls, then half, quarter
// and eighth decades around the best.
double ChooseLambda(TvFitter& fitter, double sigma, int iterations) {
  auto sure = [&](double log_lambda) {
    const double lambda = std::pow(10.0, log_lambda);
    fitter.Fit(lambda, iterations);
    return fitter.Sure(lambda, sigma);
  };
  double best_log = kLogLambdaStart, best = sure(best_log);
  for (const double step : {-1.0, 1.0}) {
    bool moved = false;
    for (double at = best_log + step; at >= kLogLambdaMin && at <= kLogLambdaMax; at += step) {
      const double value = sure(at);
      if (!(value < best)) break;
      best = value;
      best_log = at;
      moved = true;
    }
    if (moved) break;
  }
  for (double step = 0.5; step >= kSearchResolution; step /= 2.0) {
    const double center = best_log;
    for (const double at : {center - step, center + step}) {
      if (at < kLogLambdaMin || at > kLogLambdaMax) continue;
      const double value = sure(at);
      if (value < best) {
        best = value;
        best_log = at;
      }
    }
  }
  return std::pow(10.0, best_log);
}

template <typename T>
[[noreturn]] void Fail(const std::string& rule, T value) {
  std::ostringstream s;
  s << "TvDerivative: " << rule << ", got " << value;
  throw InputError(s.str());
}

}  // namespace

TvDerivativeResult TvDerivative(const Eigen::VectorXd& f, double dt,
                                const TvDerivativeOptions& options) {
  const Eigen::Index n = f.size();
  if (!(std::isfinite(dt) && dt > 0.0)) Fail("dt must be finite and > 0 [s]", dt);
  if (n < 4) Fail("need at least 4 samples", n);
  for (Eigen::Index i = 0; i < n; ++i)
    if (!std::isfinite(f(i))) Fail("sample " + std::to_string(i) + " must be finite", f(i));
  if (!std::isfinite(options.alpha)) Fail("options.alpha must be finite", options.alpha);
  if (options.iterations < 1) Fail("options.iterations must be >= 1", options.iterations);
  if (!(std::isfinite(options.epsilon) && options.epsilon > 0.0))
    Fail("options.epsilon must be finite and > 0", options.epsilon);

  const double mean = f.mean();
  double scale = std::sqrt((f.array() - mean).square().mean());
  if (!(scale > 0.0)) scale = 1.0;
  const Eigen::VectorXd g = (f.array() - mean) / scale;
  TvFitter fitter(g, options.epsilon);

  double lambda = options.alpha / (scale * dt * dt);
  if (options.alpha <= 0.0) {
    const double sigma = NoiseSd(g);
    lambda = sigma < kNoiseFloor ? 0.0 : ChooseLambda(fitter, sigma, options.iterations);
  }
  TvDerivativeResult result;
  result.iterations = fitter.Fit(lambda, options.iterations);
  result.alpha = options.alpha > 0.0 ? options.alpha : lambda * scale * dt * dt;

  const Eigen::VectorXd& w = fitter.w();
  const Eigen::VectorXd u = (w.tail(n - 1) - w.head(n - 1)) * (scale / dt);  // at midpoints
  result.derivative.resize(n);
  result.derivative.segment(1, n - 2) = 0.5 * (u.head(n - 2) + u.tail(n - 2));
  result.derivative(0) = 1.5 * u(0) - 0.5 * u(1);
  result.derivative(n - 1) = 1.5 * u(n - 2) - 0.5 * u(n - 3);
  result.value = w.array() * scale + mean;
  return result;
}

}  // namespace usvid
