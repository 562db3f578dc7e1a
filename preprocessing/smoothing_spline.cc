#include "preprocessing/smoothing_spline.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/median.h"

namespace usvid {
namespace {

// The search for mu = lambda / dt^3 (see the header): a grid of factors of kGridStep in
// [kMinMu, kMaxMu], then golden-section search around the best grid point.
constexpr double kMinMu = 1e-8;
constexpr double kMaxMu = 1e12;
constexpr double kGridStep = 10.0;
constexpr double kLogMuTolerance = 1e-2;
constexpr double kInvGoldenRatio = 0.6180339887498949;
// The even orders of the differences whose MAD estimates the noise.
constexpr int kMinNoiseOrder = 4;
constexpr int kMaxNoiseOrder = 8;

// The Reinsch system in units of samples: with D the n x (n-2) second-difference matrix
// (columns 1, -2, 1) and R' = tridiag(1/6, 2/3, 1/6),
//   (R' + mu D^T D) c = D^T y,  g = y - mu D c,  c_j = dt^2 gamma_{j+1}.
// R' + mu D^T D is pentadiagonal with constant bands; its LDL^T factor (unit L with
// sub-diagonals l1, l2 and diagonal d) is kept for the trace of the hat matrix.
class ReinschFit {
 public:
  explicit ReinschFit(const Eigen::VectorXd& y)
      : y_(y),
        rhs_(y.size() - 2),
        c_(y.size() - 2),
        g_(y.size()),
        d_(y.size() - 2),
        l1_(y.size() - 2),
        l2_(y.size() - 2),
        s0_(y.size() - 2),
        s1_(y.size() - 2) {
    for (Eigen::Index j = 0; j < rhs_.size(); ++j) rhs_(j) = y_(j) - 2.0 * y_(j + 1) + y_(j + 2);
  }

  // Fits at mu; returns the residual sum of squares sum (y - g)^2.
  double Fit(double mu) {
    const Eigen::Index m = rhs_.size();
    const double a0 = 2.0 / 3.0 + 6.0 * mu, a1 = 1.0 / 6.0 - 4.0 * mu, a2 = mu;
    for (Eigen::Index i = 0; i < m; ++i) {
      const double l1m = i >= 1 ? l1_(i - 1) : 0.0, dm = i >= 1 ? d_(i - 1) : 0.0;
      const double l2m = i >= 1 ? l2_(i - 1) : 0.0;
      const double l2mm = i >= 2 ? l2_(i - 2) : 0.0, dmm = i >= 2 ? d_(i - 2) : 0.0;
      d_(i) = a0 - l1m * l1m * dm - l2mm * l2mm * dmm;
      l1_(i) = (a1 - l2m * l1m * dm) / d_(i);
      l2_(i) = a2 / d_(i);
    }
    for (Eigen::Index i = 0; i < m; ++i) {
      c_(i) = rhs_(i) - (i >= 1 ? l1_(i - 1) * c_(i - 1) : 0.0) -
              (i >= 2 ? l2_(i - 2) * c_(i - 2) : 0.0);
    }
    for (Eigen::Index i = m - 1; i >= 0; --i) {
      c_(i) = c_(i) / d_(i) - (i + 1 < m ? l1_(i) * c_(i + 1) : 0.0) -
              (i + 2 < m ? l2_(i) * c_(i + 2) : 0.0);
    }
    double rss = 0.0;
    for (Eigen::Index i = 0; i < g_.size(); ++i) {
      const double dc = (i < m ? c_(i) : 0.0) - (i >= 1 && i - 1 < m ? 2.0 * c_(i - 1) : 0.0) +
                        (i >= 2 && i - 2 < m ? c_(i - 2) : 0.0);
      const double r = mu * dc;
      g_(i) = y_(i) - r;
      rss += r * r;
    }
    return rss;
  }

  // tr H for the hat matrix H (g = H y) of the last Fit. With S = (R' + mu D^T D)^-1,
  // H = I - mu D S D^T and mu S D^T D = I - S R', so tr H = 2 + tr(S R'), which needs only
  // the band of S: from the LDL^T factor, S = D^-1 L^-1 + (I - L^T) S, solved from the last row
  // up (Hutchinson & de Hoog 1985).
  double TraceHat() {
    const Eigen::Index m = d_.size();
    double trace = 2.0;
    for (Eigen::Index i = m - 1; i >= 0; --i) {
      const double a = i + 1 < m ? l1_(i) : 0.0, b = i + 2 < m ? l2_(i) : 0.0;
      const double s11 = i + 1 < m ? s0_(i + 1) : 0.0, s12 = i + 2 < m ? s1_(i + 1) : 0.0;
      const double s22 = i + 2 < m ? s0_(i + 2) : 0.0;
      const double s02 = -(a * s12 + b * s22);
      s1_(i) = -(a * s11 + b * s12);
      s0_(i) = 1.0 / d_(i) - (a * s1_(i) + b * s02);
      trace += 2.0 / 3.0 * s0_(i) + (i + 1 < m ? s1_(i) / 3.0 : 0.0);
    }
    return trace;
  }

  // The spline's derivative at the knots [y units per sample], from the last Fit.
  Eigen::VectorXd Derivative() const {
    const Eigen::Index n = g_.size();
    auto second = [&](Eigen::Index k) { return k == 0 || k == n - 1 ? 0.0 : c_(k - 1); };
    Eigen::VectorXd out(n);
    for (Eigen::Index i = 0; i + 1 < n; ++i)
      out(i) = g_(i + 1) - g_(i) - (2.0 * second(i) + second(i + 1)) / 6.0;
    out(n - 1) = g_(n - 1) - g_(n - 2) + (second(n - 2) + 2.0 * second(n - 1)) / 6.0;
    return out;
  }

  const Eigen::VectorXd& values() const { return g_; }

 private:
  const Eigen::VectorXd& y_;
  Eigen::VectorXd rhs_, c_, g_, d_, l1_, l2_;
  Eigen::VectorXd s0_, s1_;  // diagonal and first off-diagonal of S, for TraceHat
};

std::string Str(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// Minimises risk(log mu) on a grid of decades of mu, then by golden section around the best.
template <typename Risk>
double MinimiseOverMu(const Risk& risk) {
  const double min = std::log(kMinMu), max = std::log(kMaxMu), step = std::log(kGridStep);
  double best = min, best_risk = risk(min);
  for (double log_mu = min + step; log_mu <= max + 1e-9; log_mu += step) {
    const double r = risk(log_mu);
    if (r < best_risk) best_risk = r, best = log_mu;
  }
  double lo = std::max(best - step, min), hi = std::min(best + step, max);
  double x1 = hi - kInvGoldenRatio * (hi - lo), x2 = lo + kInvGoldenRatio * (hi - lo);
  double r1 = risk(x1), r2 = risk(x2);
  while (hi - lo > kLogMuTolerance) {
    if (r1 <= r2) {
      hi = x2, x2 = x1, r2 = r1;
      x1 = hi - kInvGoldenRatio * (hi - lo), r1 = risk(x1);
    } else {
      lo = x1, x1 = x2, r1 = r2;
      x2 = lo + kInvGoldenRatio * (hi - lo), r2 = risk(x2);
    }
  }
  if (best_risk < std::min(r1, r2)) return std::exp(best);
  return std::exp(r1 <= r2 ? x1 : x2);
}

// Mallows' C_L: RSS + 2 sd^2 tr H estimates n times the mean squared error of the fitted values
// (less a constant) without bias; minimised over log mu.
double ChooseMu(ReinschFit& fit, double noise_sd) {
  const double two_var = 2.0 * noise_sd * noise_sd;
  return MinimiseOverMu(
      [&](double log_mu) { return fit.Fit(std::exp(log_mu)) + two_var * fit.TraceHat(); });
}

void CheckInput(const Eigen::VectorXd& y, double dt, double lambda) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw InputError("smoothing spline: dt must be positive and finite, got " + Str(dt));
  if (y.size() < 4)
    throw InputError("smoothing spline: needs at least 4 samples, got " + std::to_string(y.size()));
  for (Eigen::Index i = 0; i < y.size(); ++i) {
    if (!std::isfinite(y(i)))
      throw InputError("smoothing spline: sample " + std::to_string(i) + " is not finite");
  }
  if (std::isnan(lambda) || lambda == std::numeric_limits<double>::infinity())
    throw InputError("smoothing spline: lambda must be finite (<= 0 for automatic), got " +
                     Str(lambda));
}

// One stretch between breaks: its least-squares line removed, and the Reinsch fit of the rest
// (stretches of 4 samples or more; shorter ones are their least-squares line).
struct Piece {
  Eigen::Index start = 0;
  Eigen::VectorXd s, detrended;
  double offset = 0.0, slope = 0.0;
  std::optional<ReinschFit> fit;

  Piece(const Eigen::VectorXd& y, Eigen::Index begin, Eigen::Index length) : start(begin) {
    const Eigen::VectorXd seg = y.segment(begin, length);
    s = Eigen::VectorXd::LinSpaced(length, -0.5 * (length - 1), 0.5 * (length - 1));
    offset = seg.mean();
    slope = length > 1 ? s.dot(seg) / s.squaredNorm() : 0.0;
    detrended = seg.array() - offset - slope * s.array();
    if (length >= 4) fit.emplace(detrended);
  }
};

}  // namespace

double EstimateNoiseSd(const Eigen::VectorXd& y) {
  std::vector<double> diff(y.data(), y.data() + y.size()), magnitude;
  double estimate = std::numeric_limits<double>::infinity();
  double gain = 1.0;  // C(2k, k): the variance gain of the k-th difference on white noise
  for (int k = 1; k <= kMaxNoiseOrder && diff.size() > 1; ++k) {
    for (size_t i = 0; i + 1 < diff.size(); ++i) diff[i] = diff[i + 1] - diff[i];
    diff.pop_back();
    gain = gain * (4 * k - 2) / k;
    const bool last = diff.size() == 1 || k == kMaxNoiseOrder;
    if ((k < kMinNoiseOrder || k % 2 == 1) && !(last && std::isinf(estimate))) continue;
    magnitude.resize(diff.size());
    std::transform(diff.begin(), diff.end(), magnitude.begin(),
                   [](double v) { return std::abs(v); });
    estimate = std::min(estimate, kMadToSd * SampleMedian(magnitude) / std::sqrt(gain));
  }
  return std::isfinite(estimate) ? estimate : 0.0;
}

SmoothingSplineResult SmoothingSpline(const Eigen::VectorXd& y, double dt, double lambda) {
  CheckInput(y, dt, lambda);

  // The penalty ignores straight lines, so the least-squares line is removed first: the fit
  // of what remains is the same and loses less to rounding.
  const Eigen::Index n = y.size();
  const Eigen::VectorXd s = Eigen::VectorXd::LinSpaced(n, -0.5 * (n - 1), 0.5 * (n - 1));
  const double offset = y.mean(), slope = s.dot(y) / s.squaredNorm();
  const Eigen::VectorXd detrended = y.array() - offset - slope * s.array();

  SmoothingSplineResult result;
  result.noise_sd = EstimateNoiseSd(y);
  ReinschFit fit(detrended);
  double mu = lambda / (dt * dt * dt);
  if (!(lambda > 0.0)) {
    mu = ChooseMu(fit, result.noise_sd);
  } else if (!std::isfinite(mu)) {
    throw InputError("smoothing spline: lambda / dt^3 overflows");
  }
  fit.Fit(mu);
  result.lambda = mu * dt * dt * dt;
  result.value = fit.values().array() + offset + slope * s.array();
  result.derivative = fit.Derivative().array() / dt + slope / dt;
  return result;
}

SmoothingSplineResult PiecewiseSmoothingSpline(const Eigen::VectorXd& y, double dt,
                                               const std::vector<Eigen::Index>& breaks,
                                               double lambda) {
  CheckInput(y, dt, lambda);
  std::vector<Eigen::Index> cuts = {0};
  for (Eigen::Index b : breaks)
    if (b > cuts.back() && b < y.size()) cuts.push_back(b);
  cuts.push_back(y.size());
  std::deque<Piece> pieces;  // a deque never moves its elements: each fit refers to its piece
  for (size_t k = 0; k + 1 < cuts.size(); ++k)
    pieces.emplace_back(y, cuts[k], cuts[k + 1] - cuts[k]);

  SmoothingSplineResult result;
  result.noise_sd = EstimateNoiseSd(y);
  double mu = lambda / (dt * dt * dt);
  if (!(lambda > 0.0)) {
    const double two_var = 2.0 * result.noise_sd * result.noise_sd;
    mu = MinimiseOverMu([&](double log_mu) {
      double risk = 0.0;
      for (Piece& p : pieces)
        if (p.fit) risk += p.fit->Fit(std::exp(log_mu)) + two_var * p.fit->TraceHat();
      return risk;
    });
  } else if (!std::isfinite(mu)) {
    throw InputError("smoothing spline: lambda / dt^3 overflows");
  }
  result.lambda = mu * dt * dt * dt;
  result.value.resize(y.size());
  result.derivative.resize(y.size());
  for (Piece& p : pieces) {
    const Eigen::Index n = p.s.size();
    Eigen::VectorXd g = Eigen::VectorXd::Zero(n), d = Eigen::VectorXd::Zero(n);
    if (p.fit) {
      p.fit->Fit(mu);
      g = p.fit->values();
      d = p.fit->Derivative();
    }
    result.value.segment(p.start, n) = g.array() + p.offset + p.slope * p.s.array();
    result.derivative.segment(p.start, n) = (d.array() + p.slope) / dt;
  }
  return result;
}

}  // namespace usvid
