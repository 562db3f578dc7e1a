#include "metrics/maneuver_of_record.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "core/error.h"
#include "core/parse_number.h"
#include "metrics/maneuver_header.h"
#include "metrics/turning_response.h"
#include "metrics/zigzag_response.h"

namespace usvid {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
// How far a logged rudder may lie from the angle a log's name gives [deg] (a logged angle reads a
// little off: HSVA's 10 deg is 9.94 to one side and 10.02 to the other).
constexpr double kNamedRudderToleranceDeg = 1.5;
// How far the reversal orders may lie below a named B [deg] (heading noise), and above it (a
// helm's lag, a fast vessel's turn between two samples).
constexpr double kNamedCheckBelowDeg = 1.0;
constexpr double kNamedCheckAboveDeg = 5.0;

std::string Degrees(double deg) {
  std::ostringstream s;
  s.precision(2);
  s << std::fixed << deg;
  std::string text = s.str();
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  return text;
}

// The angle the rudder is held at longest [deg], to the degree, among angles of 5 deg or more,
// with the rows at each angle; 0 when none.
std::map<long, long> RowsAtAngle(const Eigen::VectorXd& delta) {
  std::map<long, long> rows_at;
  for (const double d : delta) {
    const long deg = std::lround(std::abs(d) * kDegPerRad);
    if (deg >= 5) ++rows_at[deg];
  }
  return rows_at;
}

// "zigzag" or "turning" as the rudder holds its angle `held` [deg]; "" for no test.
std::string KindOf(const Eigen::VectorXd& delta, const std::map<long, long>& rows_at, long held) {
  long positive = 0, negative = 0, steered = 0;
  for (const auto& [deg, rows] : rows_at) steered += rows;
  for (const double d : delta) {
    const double deg = d * kDegPerRad;
    if (std::abs(std::abs(deg) - static_cast<double>(held)) <= 1.5)
      ++(deg > 0 ? positive : negative);
  }
  if (2 * (positive + negative) < steered) return "";  // no angle held: not a test
  return 5 * std::min(positive, negative) >= positive + negative ? "zigzag" : "turning";
}

[[noreturn]] void Contradicts(const Dataset& data, const std::string& named,
                              const std::string& what) {
  throw InputError(data.SourcePrefix() + "the log names its maneuver '" + named + "', but " + what +
                   " (docs/data.md#the-records-maneuver-frecordjson)");
}

}  // namespace

std::string TestOfRecord::Spec() const {
  if (kind.empty()) return "";
  const std::string a = Degrees(first_turn < 0 ? -rudder_deg : rudder_deg);
  return kind == "zigzag" ? "zigzag:" + a + "/" + Degrees(check_deg) : "turning:" + a;
}

TestOfRecord ReadTestOfRecord(const Dataset& data, const std::string& kind,
                              const std::string& heading, const std::string& rudder) {
  if (kind != "zigzag" && kind != "turning" && kind != "any")
    throw InputError("maneuver of a record: '" + kind + "' is neither zigzag, turning nor any");
  const Eigen::VectorXd& delta = data[rudder];
  (void)data[heading];  // named in the error when missing
  TestOfRecord out;
  std::optional<NamedManeuver> named;
  if (const auto it = data.metadata().find("maneuver");
      it != data.metadata().end() && !it->second.empty()) {
    const std::string where = data.Source().empty() ? "the record" : data.Source();
    named = ParseManeuverHeader(it->second, where);
    out.named = it->second;
  }
  const std::map<long, long> rows_at = RowsAtAngle(delta);
  if (rows_at.empty()) {
    if (named) Contradicts(data, out.named, "its rudder is never put over 5 deg or more");
    return out;
  }
  const long held = std::max_element(rows_at.begin(), rows_at.end(), [](auto x, auto y) {
                      return x.second < y.second;
                    })->first;
  const std::string found = KindOf(delta, rows_at, held);
  std::string test = kind;
  if (kind == "any") test = named ? named->kind : found;
  if (named && !found.empty() && found != named->kind)
    Contradicts(data, out.named, "the record holds a " + found + " test");
  // A rudder that holds no angle for most of its steering (random steps at every angle) holds no
  // test, whichever was asked for: only a log that names its test is read as that test.
  if (test.empty() || (found.empty() && !named)) return out;
  const long five = 5 * std::lround(static_cast<double>(held) / 5.0);
  double a = static_cast<double>(std::abs(held - five) <= 1 ? five : held);
  if (named) {
    if (std::abs(static_cast<double>(held) - named->rudder_deg) > kNamedRudderToleranceDeg)
      Contradicts(data, out.named, "its rudder is held at " + Degrees(held) + " deg");
    a = named->rudder_deg;
  }
  if (test == "zigzag") {
    const ZigzagCheckReading check = ReadZigzagCheck(data, heading, rudder, a);
    double b = check.check_deg;
    if (named && named->kind == "zigzag") {
      if (check.orders > 0 && (check.order_deg < named->check_deg - kNamedCheckBelowDeg ||
                               check.order_deg > named->check_deg + kNamedCheckAboveDeg))
        Contradicts(data, out.named,
                    "its rudder is reversed " + Degrees(check.order_deg) +
                        " deg off the base course, not at B = " + Degrees(named->check_deg));
      b = named->check_deg;
    } else if (!check.Consistent()) {
      return out;  // reversals at scattered headings: a rudder that switches, not a zig-zag
    }
    if (!(b > 0)) return out;
    const ZigzagResponse z = AnalyseZigzag(data, b, heading, rudder, a);
    if (z.first_turn == 0 || z.reversal_s.empty()) return out;
    out.first_turn = z.first_turn;
    out.execute_s = z.execute_s;
    out.base_offset_deg = z.base_offset_deg;
    out.check_deg = b;
  } else {
    const TurningResponse t = AnalyseTurning(data, heading, rudder, "north", "east", true, a);
    if (t.direction == 0 || !std::isfinite(t.advance_m)) return out;  // not turned by 90 deg
    out.first_turn = t.direction;
    out.execute_s = t.execute_s;
  }
  if (named && named->side != 0 && named->side != out.first_turn)
    Contradicts(data, out.named,
                std::string("the record turns to ") + (out.first_turn > 0 ? "starboard" : "port") +
                    " first (its execute at " + Degrees(out.execute_s) + " s)");
  out.kind = test;
  out.rudder_deg = a;
  return out;
}

std::string ManeuverOfRecord(const Dataset& data, const std::string& kind,
                             const std::string& heading, const std::string& rudder) {
  return ReadTestOfRecord(data, kind, heading, rudder).Spec();
}

}  // namespace usvid
