#include "importers/marin_dat.h"

#include <array>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/csv_tokenizer.h"
#include "core/error.h"
#include "core/parse_number.h"
#include "core/time_repair.h"
#include "importers/earth_to_body.h"

namespace usvid {
namespace {

constexpr int kHeaderLines = 3;
constexpr std::array<const char*, 11> kColumns = {"time", "x0", "y0", "phi",   "psi", "u",
                                                  "v",    "p",  "r",  "delta", "rev"};
constexpr double kDeg = std::numbers::pi / 180.0;

// Significant digits of a number printed as e.g. "1.35E-01" (3).
int SignificantDigits(const std::string& text) {
  int digits = 0;
  bool leading = true;
  for (char c : text) {
    if (c == 'e' || c == 'E') break;
    if (c < '0' || c > '9') continue;
    if (leading && c == '0') continue;
    leading = false;
    ++digits;
  }
  return std::max(digits, 1);
}

}  // namespace

Dataset ParseMarinDat(const std::string& text, const std::string& file, ImportReport& report) {
  const CsvTable table = TokenizeWhitespace(text, file, kHeaderLines);
  if (table.rows.empty())
    throw InputError(Located(file, 0, 0, "no data rows after the 3 header lines"));
  const auto n = static_cast<Eigen::Index>(table.rows.size());
  Eigen::MatrixXd m(n, kColumns.size());
  int time_digits = 1;
  for (Eigen::Index i = 0; i < n; ++i) {
    const CsvRow& row = table.rows[i];
    if (row.fields.size() != kColumns.size())
      throw InputError(Located(file, row.line, row.end_column,
                               "expected " + std::to_string(kColumns.size()) + " columns, found " +
                                   std::to_string(row.fields.size())));
    for (size_t c = 0; c < kColumns.size(); ++c) {
      const ParsedNumber p = ParseNumber(row.fields[c].text);
      if (p.status != NumberStatus::kOk)
        throw InputError(Located(file, row.line, row.fields[c].column,
                                 std::string("column '") + kColumns[c] +
                                     "': " + DescribeNumberStatus(p.status, row.fields[c].text)));
      m(i, c) = p.value;
    }
    time_digits = std::max(time_digits, SignificantDigits(row.fields[0].text));
  }

  Dataset data(m.col(0));
  const Eigen::VectorXd psi = m.col(4) * kDeg;
  BodyVelocities body = EarthToBody(m.col(5), m.col(6), psi);
  data.Set("north", m.col(1));
  data.Set("east", m.col(2));
  data.Set("psi", psi);
  data.Set("u", std::move(body.u));
  data.Set("v", std::move(body.v));
  data.Set("r", m.col(8) * kDeg);
  data.Set("delta", m.col(9) * kDeg);
  data.Set("rev", m.col(10));
  data.Set("phi", m.col(3) * kDeg);
  data.Set("p", m.col(7) * kDeg);
  data.metadata()["source"] = file;
  data.metadata()["format"] = "marin-dat";

  std::ostringstream s;
  s << file << ": " << n << " rows; degrees to radians (psi, r, delta, phi, p); earth-fixed "
    << "u, v rotated to body-fixed surge and sway";
  report.Note(s.str());
  const TimeRepairReport repair = RebuildRoundedTime(data, time_digits);
  report.Note(repair.Summary());
  const double max_pos =
      std::max(data["north"].cwiseAbs().maxCoeff(), data["east"].cwiseAbs().maxCoeff());
  if (max_pos > 0.0) {
    const double step = std::pow(10.0, std::floor(std::log10(max_pos)) - (time_digits - 1));
    s.str("");
    s << "positions carry " << time_digits << " significant digits: north/east resolution "
      << "coarsens to " << step << " m at |" << max_pos << "| m (left as recorded)";
    report.Note(s.str());
  }
  return data;
}

Dataset ImportMarinDat(const std::string& path, ImportReport& report) {
  return ParseMarinDat(ReadTextFile(path), path, report);
}

}  // namespace usvid
