#include "metrics/turning_response.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/angles.h"
#include "core/error.h"
#include "core/nan.h"
#include "metrics/criteria_smoothing.h"
#include "metrics/maneuver_execute.h"

namespace usvid {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A channel's sampled (finite) values in time order.
struct Samples {
  std::vector<double> t, x;
};

Samples Sampled(const Eigen::VectorXd& t, const Eigen::VectorXd& x) {
  Samples s;
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    if (!std::isfinite(x(k))) continue;
    s.t.push_back(t(k));
    s.x.push_back(x(k));
  }
  return s;
}

// A channel's samples, smoothed when they lie on a uniform grid (criteria_smoothing.h).
Samples SmoothedSamples(const Eigen::VectorXd& t, const Eigen::VectorXd& x) {
  Samples s = Sampled(t, x);
  const Eigen::Index n = static_cast<Eigen::Index>(s.x.size());
  const Eigen::VectorXd smoothed =
      SmoothedForCriteria(Eigen::Map<const Eigen::VectorXd>(s.t.data(), n),
                          Eigen::Map<const Eigen::VectorXd>(s.x.data(), n));
  Eigen::Map<Eigen::VectorXd>(s.x.data(), n) = smoothed;
  return s;
}

// Linear between the samples around `time`; NaN outside them.
double At(const Samples& s, double time) {
  const auto it = std::lower_bound(s.t.begin(), s.t.end(), time);
  if (it == s.t.end()) return kNaN;
  const size_t k = it - s.t.begin();
  if (s.t[k] == time) return s.x[k];
  if (k == 0) return kNaN;
  const double f = (time - s.t[k - 1]) / (s.t[k] - s.t[k - 1]);
  return s.x[k - 1] + f * (s.x[k] - s.x[k - 1]);
}

// The time at which `turned` first reaches `target`, or NaN.
double FirstCrossing(const Samples& turned, double target) {
  for (size_t k = 1; k < turned.t.size(); ++k) {
    if (turned.x[k] < target) continue;
    const double f = (target - turned.x[k - 1]) / (turned.x[k] - turned.x[k - 1]);
    return turned.t[k - 1] + f * (turned.t[k] - turned.t[k - 1]);
  }
  return kNaN;
}

// The time after which `turned` stays above `target` (its last upward crossing), or NaN.
double LastCrossing(const Samples& turned, double target) {
  for (size_t k = turned.t.size(); k-- > 1;) {
    if (turned.x[k - 1] > target) continue;
    const double f = (target - turned.x[k - 1]) / (turned.x[k] - turned.x[k - 1]);
    return turned.t[k - 1] + f * (turned.t[k] - turned.t[k - 1]);
  }
  return kNaN;
}

// Radius of the algebraic least-squares circle (Kasa) through the positions sampled within
// [from, to], or NaN for fewer than three.
double CircleRadius(const Eigen::VectorXd& t, const Eigen::VectorXd& north,
                    const Eigen::VectorXd& east, double from, double to) {
  std::vector<Eigen::Vector2d> p;
  for (Eigen::Index k = 0; k < t.size(); ++k)
    if (t(k) >= from && t(k) <= to && std::isfinite(north(k)) && std::isfinite(east(k)))
      p.emplace_back(north(k), east(k));
  if (p.size() < 3) return kNaN;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& q : p) mean += q / static_cast<double>(p.size());
  // x^2 + y^2 + D x + E y + F = 0, centred on the mean for conditioning.
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const auto& q : p) {
    const Eigen::Vector2d c = q - mean;
    const Eigen::Vector3d row(c.x(), c.y(), 1.0);
    a += row * row.transpose();
    b -= row * c.squaredNorm();
  }
  const Eigen::Vector3d def = a.ldlt().solve(b);
  const double r2 = (def(0) * def(0) + def(1) * def(1)) / 4 - def(2);
  return r2 > 0 ? std::sqrt(r2) : kNaN;
}

}  // namespace

TurningResponse AnalyseTurning(const Dataset& data, const std::string& heading,
                               const std::string& rudder, const std::string& north,
                               const std::string& east, bool find_execute, double rudder_deg) {
  for (const std::string& c : {heading, rudder, north, east})
    if (!data.Has(c)) {
      data.CheckNotText(c);
      throw InputError(data.SourcePrefix() + "turning circle: no channel '" + c + "'");
    }
  const Eigen::VectorXd& t = data.t();
  const Samples delta = Sampled(t, data[rudder]);
  double largest = 0.0;
  for (double d : delta.x) largest = std::max(largest, std::abs(d));
  const double moved = largest <= std::numbers::pi / 2 ? kDeg : 0.01 * largest;
  // a log's heading may wrap; a noisy one is smoothed, as are the positions
  const Samples psi = SmoothedSamples(t, UnwrappedAngle(data[heading]));
  std::vector<double> heading_at(delta.t.size());
  for (size_t k = 0; k < delta.t.size(); ++k) heading_at[k] = At(psi, delta.t[k]);
  const long first = find_execute ? FindExecute(delta.x, heading_at, moved, 90.0 * kDeg,
                                                std::abs(rudder_deg) * kDeg)
                                  : -1;
  double execute = first >= 0 ? delta.t[first] : kNaN;
  for (size_t k = 0; k < delta.x.size() && std::isnan(execute); ++k)
    if (std::abs(delta.x[k] - delta.x[0]) > moved) execute = delta.t[k];
  if (std::isnan(execute))
    throw InputError(data.SourcePrefix() + "turning circle: the rudder '" + rudder +
                     "' never moves");

  TurningResponse z;
  z.execute_s = execute;
  z.advance_m = z.transfer_m = z.tactical_diameter_m = kNaN;
  z.steady_rate_deg_s = z.steady_radius_m = kNaN;
  const Samples n = SmoothedSamples(t, data[north]), e = SmoothedSamples(t, data[east]);
  const double psi0 = At(psi, execute), n0 = At(n, execute), e0 = At(e, execute);
  if (std::isnan(psi0)) return z;

  // The heading change from the execute on, then signed to the turning side.
  Samples turned{{execute}, {0.0}};
  for (size_t k = 0; k < psi.t.size(); ++k) {
    if (psi.t[k] <= execute) continue;
    turned.t.push_back(psi.t[k]);
    turned.x.push_back(psi.x[k] - psi0);
  }
  double furthest = 0.0;
  for (double x : turned.x)
    if (std::abs(x) > std::abs(furthest)) furthest = x;
  if (furthest == 0.0) return z;
  z.direction = furthest > 0 ? 1 : -1;
  for (double& x : turned.x) x *= z.direction;

  const double c = std::cos(psi0), s = std::sin(psi0);
  auto along = [&](double time) { return (At(n, time) - n0) * c + (At(e, time) - e0) * s; };
  auto across = [&](double time) {
    return z.direction * (-(At(n, time) - n0) * s + (At(e, time) - e0) * c);
  };
  const double t90 = FirstCrossing(turned, 90 * kDeg);
  z.reached_90 = !std::isnan(t90);
  if (z.reached_90) {
    z.advance_m = along(t90);
    z.transfer_m = across(t90);
  }
  const double t180 = FirstCrossing(turned, 180 * kDeg);
  z.reached_180 = !std::isnan(t180);
  if (z.reached_180) z.tactical_diameter_m = across(t180);

  const double turned_end = turned.x.back(), t_end = turned.t.back();
  if (z.reached_180 && turned_end >= 540 * kDeg) {
    const double from = LastCrossing(turned, turned_end - 360 * kDeg);
    z.steady_rate_deg_s = 360.0 / (t_end - from);
    z.steady_radius_m = CircleRadius(t, data[north], data[east], from, t_end);
  }
  return z;
}

}  // namespace usvid
