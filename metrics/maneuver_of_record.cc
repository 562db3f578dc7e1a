#include "metrics/maneuver_of_record.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "core/error.h"
#include "metrics/turning_response.h"
#include "metrics/zigzag_response.h"

namespace usvid {

std::string ManeuverOfRecord(const Dataset& data, const std::string& kind,
                             const std::string& heading, const std::string& rudder) {
  if (kind != "zigzag" && kind != "turning")
    throw InputError("maneuver of a record: '" + kind + "' is neither zigzag nor turning");
  const Eigen::VectorXd& delta = data[rudder];
  (void)data[heading];  // named in the error when missing
  // The angle the rudder is held at longest, to the degree, among angles of 5 deg or more.
  std::map<long, long> rows_at;
  for (const double d : delta) {
    const long deg = std::lround(std::abs(d) * 180.0 / std::numbers::pi);
    if (deg >= 5) ++rows_at[deg];
  }
  if (rows_at.empty()) return "";
  const auto held = std::max_element(rows_at.begin(), rows_at.end(),
                                     [](auto x, auto y) { return x.second < y.second; });
  const long five = 5 * std::lround(static_cast<double>(held->first) / 5.0);
  const int a = static_cast<int>(std::abs(held->first - five) <= 1 ? five : held->first);
  if (kind == "zigzag") {
    const ZigzagResponse z = AnalyseZigzag(data, a, heading, rudder, a);
    if (z.first_turn == 0 || z.reversal_s.empty()) return "";
    return "zigzag:" + std::to_string(z.first_turn * a) + "/" + std::to_string(a);
  }
  const TurningResponse t = AnalyseTurning(data, heading, rudder, "north", "east", true, a);
  if (t.direction == 0 || !std::isfinite(t.advance_m)) return "";  // not turned by 90 deg
  return "turning:" + std::to_string(t.direction * a);
}

}  // namespace usvid
