#include "metrics/zigzag_response.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/angles.h"
#include "core/error.h"
#include "metrics/criteria_smoothing.h"
#include "metrics/maneuver_execute.h"

namespace usvid {
namespace {

// The base course less the heading at the execute [rad]: the mean midpoint of successive reversal
// orders' headings (zigzag_response.h). An order is the last sample of its leg at the leg's full
// angle (within kOrderToleranceRad: a log's rudder flickers in its last digit about the angle it
// holds), and its heading the mean of that sample's and the next, to within half their
// difference. Two successive orders pair when their headings lie at least B apart, as a leg's
// two ends do (base - B and base + B): a rudder that flickers through zero, or is put over for
// a sample as the test stops, makes a crossing whose order is no leg's end. 0 without a pair,
// where the offset is within the orders' resolution (a fast vessel turns a degree between two
// samples, and would otherwise read a different base course on every record), or where the test
// is not clean (zigzag_response.h): a test is taken to reverse about its heading at the execute,
// ITTC's base course, unless its record shows another plainly.
double BaseCourseOffset(const Eigen::VectorXd& psi, const Eigen::VectorXd& delta,
                        Eigen::Index execute, const std::vector<Eigen::Index>& reversals,
                        double threshold_rad) {
  constexpr double kOrderToleranceRad = 1.0 * std::numbers::pi / 180.0;
  constexpr double kOrderSpreadRad = 0.5 * std::numbers::pi / 180.0;
  constexpr double kHelmLagRad = 2.0 * std::numbers::pi / 180.0;
  struct Order {
    double heading, half_width;  // to within half_width
    bool paired = false;
  };
  std::vector<Order> orders;
  Eigen::Index leg_start = execute;
  for (const Eigen::Index reversal : reversals) {
    const double side = delta(reversal - 1) > 0 ? 1.0 : -1.0;
    double full = -INFINITY;
    for (Eigen::Index k = leg_start; k < reversal; ++k) full = std::max(full, side * delta(k));
    Eigen::Index order = reversal - 1;
    while (order > leg_start && side * delta(order) < full - kOrderToleranceRad) --order;
    orders.push_back(
        {0.5 * (psi(order) + psi(order + 1)), 0.5 * std::abs(psi(order + 1) - psi(order))});
    leg_start = reversal;
  }
  double sum = 0.0, resolution = 0.0;
  int pairs = 0;
  for (size_t i = 0; i + 1 < orders.size(); ++i) {
    Order &a = orders[i], &b = orders[i + 1];
    if (std::abs(b.heading - a.heading) < threshold_rad) continue;
    a.paired = b.paired = true;
    sum += 0.5 * (a.heading + b.heading);
    resolution += 0.5 * (a.half_width + b.half_width);
    ++pairs;
  }
  if (pairs == 0) return 0.0;
  const double base = sum / pairs, offset = base - psi(execute);
  if (!(std::abs(offset) > resolution / pairs)) return 0.0;
  // A clean test: every paired order as far from the base course as the others, and that B
  // plus a helm's lag.
  double nearest = INFINITY, furthest = 0.0;
  for (const Order& o : orders) {
    if (!o.paired) continue;
    nearest = std::min(nearest, std::abs(o.heading - base));
    furthest = std::max(furthest, std::abs(o.heading - base));
  }
  const bool clean = furthest - nearest <= 2.0 * kOrderSpreadRad &&
                     nearest >= threshold_rad - kOrderSpreadRad &&
                     furthest <= threshold_rad + kHelmLagRad;
  return clean ? offset : 0.0;
}

// The reversals after the execute: where the rudder crosses zero on its way from one side's leg
// to the other's. A crossing counts once the rudder has gone on to half its largest angle after
// the execute on the new side: noise or a flicker about zero as the rudder is put over (a
// disturbed record's), or the rudder set back to zero as the test stops, reverses nothing. The
// reversal is the first sample of the run of samples on the new side that reaches it. Unit-free:
// the yaw command may be a rudder angle, a nozzle angle or a moment.
std::vector<Eigen::Index> Reversals(const Eigen::VectorXd& delta, Eigen::Index execute) {
  const Eigen::Index n = delta.size();
  double largest = 0.0;
  for (Eigen::Index k = execute; k < n; ++k) largest = std::max(largest, std::abs(delta(k)));
  const double half = 0.5 * largest;
  std::vector<Eigen::Index> reversals;
  int side = 0;  // the side of the last leg that reached half the angle
  Eigen::Index run_start = execute;
  for (Eigen::Index k = execute; k < n; ++k) {
    if (k > execute && (delta(k) > 0) != (delta(k - 1) > 0)) run_start = k;
    if (!(std::abs(delta(k)) >= half) || half <= 0) continue;
    const int here = delta(k) > 0 ? 1 : -1;
    if (side != 0 && here != side) reversals.push_back(std::max(run_start, execute + 1));
    side = here;
  }
  return reversals;
}

// The heading check of a test whose orders lie `order_deg` from its base course, with rudder
// angle `rudder_deg`: A itself within kCheckNearRudderDeg (10/10 and 20/20 are the usual
// tests, and a hand-steered one orders a few degrees early or late), else the nearest preferred
// check: 1 deg (a big ship's smallest zig-zag, HSVA's KVLCC2 10/1 and 15/1, whose helm orders it
// up to 1 deg late), then every 5 deg.
double NearestCheck(double order_deg, double rudder_deg) {
  if (!(order_deg > 0.5)) return 0.0;
  if (rudder_deg > 0 && std::abs(order_deg - rudder_deg) <= kCheckNearRudderDeg) return rudder_deg;
  if (order_deg < 3.0) return 1.0;
  return std::min(90.0, 5.0 * std::round(order_deg / 5.0));
}

}  // namespace

bool ZigzagCheckReading::Consistent() const {
  if (half_swings >= 2) return 3 * agreeing >= 2 * half_swings;
  if (half_swings == 1 && first_order_deg > 0)
    return std::abs(first_order_deg - order_deg) <= std::max(kCheckAgreementDeg, 0.25 * order_deg);
  return true;
}

ZigzagCheckReading ReadZigzagCheck(const Dataset& data, const std::string& heading,
                                   const std::string& rudder, double rudder_deg) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  for (const std::string& c : {heading, rudder})
    if (!data.Has(c)) {
      data.CheckNotText(c);
      throw InputError(data.SourcePrefix() + "zig-zag: no channel '" + c + "'");
    }
  const Eigen::VectorXd psi = SmoothedForCriteria(data.t(), UnwrappedAngle(data[heading]));
  const Eigen::VectorXd& delta = data[rudder];
  const Eigen::Index n = data.rows();
  double full = rudder_deg > 0 ? rudder_deg * kDeg : delta.cwiseAbs().maxCoeff();
  const double at_full = full - std::max(kDeg, 0.1 * full);
  // The legs at full angle: (side, last sample).
  std::vector<std::pair<int, Eigen::Index>> legs;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!(std::abs(delta(k)) >= at_full) || full <= 0) continue;
    const int side = delta(k) > 0 ? 1 : -1;
    if (!legs.empty() && legs.back().first == side && legs.back().second == k - 1)
      legs.back().second = k;
    else
      legs.emplace_back(side, k);
  }
  // An order: a leg's end followed by a leg to the other side. Its heading: the mean of its
  // last sample's and the one before, which bracket the heading at which it was ordered when
  // the helm answers at once (a simulated test reverses at the first sample past B).
  auto order_heading = [&](Eigen::Index end) {
    return 0.5 * (psi(std::max<Eigen::Index>(end - 1, 0)) + psi(end));
  };
  std::vector<double> half_swings;
  ZigzagCheckReading out;
  for (size_t i = 0; i + 1 < legs.size(); ++i) {
    if (legs[i].first == legs[i + 1].first) continue;
    ++out.orders;
    if (i + 2 < legs.size() && legs[i + 2].first != legs[i + 1].first)
      half_swings.push_back(
          0.5 * std::abs(order_heading(legs[i + 1].second) - order_heading(legs[i].second)));
  }
  if (!half_swings.empty()) {
    std::nth_element(half_swings.begin(), half_swings.begin() + half_swings.size() / 2,
                     half_swings.end());
    out.order_deg = half_swings[half_swings.size() / 2] / kDeg;
    out.half_swings = static_cast<int>(half_swings.size());
    const double within = std::max(kCheckAgreementDeg, 0.25 * out.order_deg) * kDeg;
    for (const double h : half_swings)
      if (std::abs(h - out.order_deg * kDeg) <= within) ++out.agreeing;
  }
  // The first order's heading from the heading at the execute: B with one reversal, and with
  // two a check that the one half swing is a zig-zag's (ZigzagCheckReading::Consistent).
  if (out.orders >= 1) {
    const long execute = FindExecute({delta.data(), static_cast<size_t>(n)},
                                     {psi.data(), static_cast<size_t>(n)}, kDeg, 0.0, full);
    if (execute >= 0) {
      for (const auto& [side, end] : legs)
        if (end > execute) {
          out.first_order_deg = std::abs(order_heading(end) - psi(execute)) / kDeg;
          break;
        }
    }
    if (out.orders == 1) out.order_deg = out.first_order_deg;
  }
  out.check_deg = NearestCheck(out.order_deg, rudder_deg > 0 ? rudder_deg : full / kDeg);
  return out;
}

ZigzagResponse AnalyseZigzag(const Dataset& data, double threshold_deg, const std::string& heading,
                             const std::string& rudder, double rudder_deg) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  for (const std::string& c : {heading, rudder})
    if (!data.Has(c)) {
      data.CheckNotText(c);
      throw InputError(data.SourcePrefix() + "zig-zag: no channel '" + c + "'");
    }
  const Eigen::VectorXd& t = data.t();
  // a log's heading may wrap; a noisy one is smoothed (criteria_smoothing.h)
  const Eigen::VectorXd psi = SmoothedForCriteria(t, UnwrappedAngle(data[heading]));
  const Eigen::VectorXd& delta = data[rudder];
  const Eigen::Index n = data.rows();
  Eigen::Index execute = rudder_deg < 0
                             ? -1
                             : FindExecute({delta.data(), static_cast<size_t>(n)},
                                           {psi.data(), static_cast<size_t>(n)}, kDeg,
                                           std::abs(threshold_deg) * kDeg, rudder_deg * kDeg);
  for (Eigen::Index k = 0; k < n && execute < 0; ++k)
    if (std::abs(delta(k) - delta(0)) > kDeg) execute = k;
  if (execute < 0) throw InputError(data.SourcePrefix() + "zig-zag: the rudder never moves");
  ZigzagResponse z;
  z.execute_s = t(execute);
  const std::vector<Eigen::Index> reversals = Reversals(delta, execute);
  const double base =
      psi(execute) + BaseCourseOffset(psi, delta, execute, reversals, threshold_deg * kDeg);
  z.base_offset_deg = (base - psi(execute)) / kDeg;
  for (size_t i = 0; i < reversals.size(); ++i) {
    const Eigen::Index a = reversals[i];
    const Eigen::Index b = i + 1 < reversals.size() ? reversals[i + 1] : n;
    const double direction = psi(a) - base >= 0 ? 1.0 : -1.0;
    if (i == 0) z.first_turn = static_cast<int>(direction);
    double furthest = -INFINITY;
    for (Eigen::Index k = a; k < b; ++k) furthest = std::max(furthest, direction * (psi(k) - base));
    z.reversal_s.push_back(t(a));
    z.overshoot_deg.push_back(furthest / kDeg - threshold_deg);
  }
  return z;
}

}  // namespace usvid
