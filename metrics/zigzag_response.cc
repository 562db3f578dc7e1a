#include "metrics/zigzag_response.h"

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
// angle (within kOrderToleranceDeg: a log's rudder flickers in its last digit about the angle it
// holds), and its heading the mean of that sample's and the next, to within half their
// difference. 0 with fewer than two orders, or where the offset is within that resolution: a
// test is taken to reverse about its heading at the execute (ITTC's base course) unless its
// record shows otherwise. A fast vessel turns a degree between two samples, and would otherwise
// read a different base course on every record.
double BaseCourseOffset(const Eigen::VectorXd& psi, const Eigen::VectorXd& delta,
                        Eigen::Index execute, const std::vector<Eigen::Index>& reversals) {
  constexpr double kOrderToleranceRad = 1.0 * std::numbers::pi / 180.0;
  std::vector<double> ordered_at, half_width;
  Eigen::Index leg_start = execute;
  for (const Eigen::Index reversal : reversals) {
    const double side = delta(reversal - 1) > 0 ? 1.0 : -1.0;
    double full = -INFINITY;
    for (Eigen::Index k = leg_start; k < reversal; ++k) full = std::max(full, side * delta(k));
    Eigen::Index order = reversal - 1;
    while (order > leg_start && side * delta(order) < full - kOrderToleranceRad) --order;
    ordered_at.push_back(0.5 * (psi(order) + psi(order + 1)));
    half_width.push_back(0.5 * std::abs(psi(order + 1) - psi(order)));
    leg_start = reversal;
  }
  if (ordered_at.size() < 2) return 0.0;
  double sum = 0.0, resolution = 0.0;
  for (size_t i = 0; i + 1 < ordered_at.size(); ++i) {
    sum += 0.5 * (ordered_at[i] + ordered_at[i + 1]);
    resolution += 0.5 * (half_width[i] + half_width[i + 1]);
  }
  const auto pairs = static_cast<double>(ordered_at.size() - 1);
  const double offset = sum / pairs - psi(execute);
  return std::abs(offset) > resolution / pairs ? offset : 0.0;
}

}  // namespace

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
  Eigen::Index execute =
      rudder_deg < 0
          ? -1
          : FindExecute({delta.data(), static_cast<size_t>(n)},
                        {psi.data(), static_cast<size_t>(n)}, kDeg,
                        std::abs(threshold_deg) * kDeg, rudder_deg * kDeg);
  for (Eigen::Index k = 0; k < n && execute < 0; ++k)
    if (std::abs(delta(k) - delta(0)) > kDeg) execute = k;
  if (execute < 0) throw InputError(data.SourcePrefix() + "zig-zag: the rudder never moves");
  ZigzagResponse z;
  z.execute_s = t(execute);
  std::vector<Eigen::Index> reversals;
  for (Eigen::Index k = execute + 1; k < n; ++k)
    if ((delta(k) > 0) != (delta(k - 1) > 0)) reversals.push_back(k);
  const double base = psi(execute) + BaseCourseOffset(psi, delta, execute, reversals);
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
