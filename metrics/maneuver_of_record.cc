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
  if (kind != "zigzag" && kind != "turning" && kind != "any")
    throw InputError("maneuver of a record: '" + kind + "' is neither zigzag, turning nor any");
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
  if (kind == "any") {
    // The rows at the held angle (within 1.5 deg) to either side, against every row at 5 deg or
    // more: a test holds its angle most of the time, a zig-zag to both sides, a turn to one.
    long positive = 0, negative = 0, steered = 0;
    for (const auto& [deg, rows] : rows_at) steered += rows;
    for (const double d : delta) {
      const double deg = d * 180.0 / std::numbers::pi;
      if (std::abs(std::abs(deg) - static_cast<double>(held->first)) <= 1.5)
        ++(deg > 0 ? positive : negative);
    }
    if (2 * (positive + negative) < steered) return "";  // no angle held: not a test
    const bool both_sides = 5 * std::min(positive, negative) >= positive + negative;
    return ManeuverOfRecord(data, both_sides ? "zigzag" : "turning", heading, rudder);
  }
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
