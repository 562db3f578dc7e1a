#include "importers/hsva_dat.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string_view>

#include "core/csv_tokenizer.h"
#include "core/error.h"
#include "core/parse_number.h"
#include "importers/earth_to_body.h"

namespace usvid {
namespace {

constexpr int kHsvaHeaderLines = 4;
constexpr int kHsvaManeuverLine = 3;
constexpr std::array<const char*, kHsvaHeaderLines> kHsvaHeaderNames = {"institute", "ship",
                                                                        "maneuver", "title"};
constexpr std::array<const char*, 12> kHsvaColumns = {
    "time", "x0", "y0", "psi", "dx0/dt", "dy0/dt", "r", "phi", "delta", "rev", "thrust", "torque"};
constexpr double kHsvaDeg = std::numbers::pi / 180.0;

// Windows-1252's bytes 0x80-0x9F as Unicode code points; 0 where it defines none.
constexpr std::array<char32_t, 32> kCp1252High = {
    0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
    0x2039, 0x0152, 0,      0x017D, 0,      0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
    0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};

void AppendUtf8(char32_t c, std::string& out) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

// One header line from cp1252 to UTF-8; columns in errors are the file's bytes.
std::string HeaderLineToUtf8(std::string_view line, const std::string& file, int line_no) {
  std::string out;
  for (size_t i = 0; i < line.size(); ++i) {
    const auto b = static_cast<unsigned char>(line[i]);
    char32_t c = b;
    if (b >= 0x80 && b < 0xA0) c = kCp1252High[b - 0x80];
    if ((b < 0x20 && b != '\t') || b == 0x7F || c == 0) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", b);
      throw InputError(Located(file, line_no, static_cast<int>(i) + 1,
                               std::string("byte ") + hex + " is not cp1252 text"));
    }
    AppendUtf8(c, out);
  }
  return out;
}

std::string Trimmed(const std::string& s) {
  const size_t first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// A header line that is a row of numbers: the file lacks header lines.
bool IsRowOfNumbers(const std::string& line) {
  std::istringstream s(line);
  int count = 0;
  for (std::string word; s >> word; ++count)
    if (ParseNumber(word).status != NumberStatus::kOk) return false;
  return count >= 2;
}

// The 4 header lines, in cp1252, turned to UTF-8; `pos` ends at the first data row.
std::array<std::string, kHsvaHeaderLines> ReadHeader(const std::string& text,
                                                     const std::string& file, size_t& pos) {
  std::array<std::string, kHsvaHeaderLines> header;
  pos = 0;
  int lines = 0;
  while (lines < kHsvaHeaderLines && pos < text.size()) {
    const size_t end = std::min(text.find('\n', pos), text.size());
    std::string_view line(text.data() + pos, end - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    header[lines] = HeaderLineToUtf8(line, file, lines + 1);
    ++lines;
    if (IsRowOfNumbers(header[lines - 1]))
      throw InputError(Located(file, lines, 1,
                               std::string("a row of numbers where header line ") +
                                   std::to_string(lines) + " (" + kHsvaHeaderNames[lines - 1] +
                                   ") belongs: an HSVA file starts with 4 header lines "
                                   "(institute, ship, maneuver, title)"));
    pos = std::min(end + 1, text.size());
  }
  if (lines < kHsvaHeaderLines)
    throw InputError(Located(file, lines, 0,
                             "the file ends after " + std::to_string(lines) +
                                 " lines: an HSVA file starts with 4 header lines (institute, "
                                 "ship, maneuver, title), then the data rows"));
  return header;
}

// The data rows as numbers, one column per kHsvaColumns, time increasing; an error names the
// file:line:column of the first bad cell.
Eigen::MatrixXd ReadRows(const CsvTable& table, const std::string& file) {
  const auto n = static_cast<Eigen::Index>(table.rows.size());
  Eigen::MatrixXd m(n, kHsvaColumns.size());
  for (Eigen::Index i = 0; i < n; ++i) {
    const CsvRow& row = table.rows[i];
    if (row.fields.size() != kHsvaColumns.size())
      throw InputError(Located(file, row.line, row.end_column,
                               "expected " + std::to_string(kHsvaColumns.size()) +
                                   " columns, found " + std::to_string(row.fields.size())));
    for (size_t c = 0; c < kHsvaColumns.size(); ++c) {
      const ParsedNumber p = ParseNumber(row.fields[c].text);
      if (p.status != NumberStatus::kOk)
        throw InputError(Located(file, row.line, row.fields[c].column,
                                 std::string("column '") + kHsvaColumns[c] +
                                     "': " + DescribeNumberStatus(p.status, row.fields[c].text)));
      m(i, static_cast<Eigen::Index>(c)) = p.value;
    }
    if (i > 0 && m(i, 0) <= m(i - 1, 0))
      throw InputError(Located(file, row.line, row.fields[0].column,
                               "time " + FormatNumber(m(i, 0)) +
                                   (m(i, 0) == m(i - 1, 0) ? " repeats" : " goes back from") +
                                   " the previous " + FormatNumber(m(i - 1, 0)) +
                                   "; it must increase from row to row"));
  }
  return m;
}

}  // namespace

Dataset ParseHsvaDat(const std::string& text, const std::string& file, ImportReport& report) {
  // The header, in cp1252, read here; the data rows, ASCII, by the tokenizer, which checks them
  // as text and keeps their line numbers (the header is blanked for it).
  size_t pos = 0;
  const std::array<std::string, kHsvaHeaderLines> header = ReadHeader(text, file, pos);
  const std::string maneuver = Trimmed(header[kHsvaManeuverLine - 1]);
  if (maneuver.empty())
    throw InputError(Located(file, kHsvaManeuverLine, 0,
                             "header line 3 (the maneuver, e.g. 'Z20°/10° starting to "
                             "starboard') is empty"));

  std::string body(kHsvaHeaderLines, '\n');
  body.append(text, pos);
  const CsvTable table = TokenizeWhitespace(body, file, kHsvaHeaderLines);
  if (table.rows.empty())
    throw InputError(Located(file, kHsvaHeaderLines, 0, "no data rows after the 4 header lines"));
  const Eigen::MatrixXd m = ReadRows(table, file);

  Dataset data(m.col(0));
  const Eigen::VectorXd psi = m.col(3) * kHsvaDeg;
  BodyVelocities body_velocities = EarthToBody(m.col(4), m.col(5), psi);
  data.Set("north", m.col(1));
  data.Set("east", m.col(2));
  data.Set("psi", psi);
  data.Set("u", std::move(body_velocities.u));
  data.Set("v", std::move(body_velocities.v));
  data.Set("r", m.col(6) * kHsvaDeg);
  data.Set("delta", m.col(8) * kHsvaDeg);
  data.Set("rev", m.col(9) * 60.0);
  data.Set("phi", m.col(7) * kHsvaDeg);
  data.Set("thrust", m.col(10));
  data.Set("torque", m.col(11));
  data.metadata()["source"] = file;
  data.metadata()["format"] = "hsva-dat";
  data.metadata()["maneuver"] = maneuver;

  std::ostringstream s;
  s << file << ": " << m.rows() << " rows, " << Trimmed(header[0]) << ", " << Trimmed(header[1])
    << ", maneuver '" << maneuver << "' (header line 3, kept in the record, not interpreted); "
    << "degrees to radians (psi, r, delta, phi), rev from rps to rpm; earth-fixed dx0/dt, dy0/dt "
    << "rotated to body-fixed surge and sway; at the log's scale";
  report.Note(s.str());
  return data;
}

Dataset ImportHsvaDat(const std::string& path, ImportReport& report) {
  return ParseHsvaDat(ReadTextFile(path), path, report);
}

}  // namespace usvid
