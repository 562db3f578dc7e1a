#include "metrics/zigzag_response.h"

#include <cmath>
#include <numbers>

#include "core/angles.h"
#include "core/error.h"
#include "metrics/criteria_smoothing.h"
#include "metrics/maneuver_execute.h"

namespace usvid {

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
  const double psi0 = psi(execute);
  std::vector<Eigen::Index> reversals;
  for (Eigen::Index k = execute + 1; k < n; ++k)
    if ((delta(k) > 0) != (delta(k - 1) > 0)) reversals.push_back(k);
  for (size_t i = 0; i < reversals.size(); ++i) {
    const Eigen::Index a = reversals[i];
    const Eigen::Index b = i + 1 < reversals.size() ? reversals[i + 1] : n;
    const double direction = psi(a) - psi0 >= 0 ? 1.0 : -1.0;
    if (i == 0) z.first_turn = static_cast<int>(direction);
    double furthest = -INFINITY;
    for (Eigen::Index k = a; k < b; ++k) furthest = std::max(furthest, direction * (psi(k) - psi0));
    z.reversal_s.push_back(t(a));
    z.overshoot_deg.push_back(furthest / kDeg - threshold_deg);
  }
  return z;
}

}  // namespace usvid
