#include "importers/csv_log.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/angles.h"
#include "core/csv_tokenizer.h"
#include "core/error.h"
#include "core/parse_number.h"
#include "core/time_repair.h"
#include "importers/earth_to_body.h"

namespace usvid {
namespace {

char DetectSeparator(const std::string& text) {
  const std::string header = text.substr(0, text.find('\n'));
  char best = ',';
  long best_count = 0;
  for (char sep : {',', ';', '\t'}) {
    const long count = std::count(header.begin(), header.end(), sep);
    if (count > best_count) {
      best = sep;
      best_count = count;
    }
  }
  return best;
}

std::string SeparatorName(char sep) { return sep == '\t' ? "tab" : std::string(1, sep); }

// A heading logged within -pi..pi (or 0..2 pi) jumps by 2 pi when the vessel turns through the
// wrap: unwrapped, so that a turning circle's heading runs on, and said.
void UnwrapHeadings(Dataset& data, ImportReport& report) {
  for (const char* name : {"psi", "chi"}) {
    if (!data.Has(name)) continue;
    const Channel& c = data.Get(name);
    const Eigen::VectorXd unwrapped = UnwrappedAngle(c.values());
    Eigen::Index jumps = 0;
    double last = NAN;
    for (Eigen::Index k = 0; k < c.values().size(); ++k) {
      if (!c.IsSampled(k)) continue;
      if (std::isfinite(last) && std::abs((unwrapped(k) - c.Value(k)) - last) > 1.0) ++jumps;
      last = unwrapped(k) - c.Value(k);
    }
    if (jumps == 0) continue;
    report.Note(std::string(name) + ": unwrapped " + std::to_string(jumps) +
                (jumps == 1 ? " jump" : " jumps") + " of 2 pi (a heading logged within one turn)");
    data.Set(name, unwrapped, c.sampled());
  }
}

}  // namespace

std::vector<std::string> CsvLogColumns(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file for reading");
  std::string header;
  std::getline(in, header);
  if (!header.empty() && header.back() == '\r') header.pop_back();
  if (header.empty()) throw InputError(Located(path, 1, 0, "no header line"));
  CsvRow row;
  SplitCsvLine(header, path, 1, DetectSeparator(header), row);
  std::vector<std::string> out;
  for (const CsvField& f : row.fields) out.push_back(f.text);
  return out;
}

namespace {

// The data rows of a table: rows with every cell empty (a logger's trailing padding) hold
// nothing, and are dropped, and counted.
struct DataRows {
  std::vector<const CsvRow*> rows;
  int first_empty_line = 0;
  long empty_rows = 0;
};

DataRows RowsWithData(const CsvTable& table) {
  DataRows out;
  for (size_t i = 1; i < table.rows.size(); ++i) {
    const CsvRow& row = table.rows[i];
    if (std::all_of(row.fields.begin(), row.fields.end(),
                    [](const CsvField& f) { return IsBlankLine(f.text); })) {
      if (out.empty_rows++ == 0) out.first_empty_line = row.line;
      continue;
    }
    out.rows.push_back(&row);
  }
  return out;
}

struct MappedColumn {
  Eigen::VectorXd values;
  Eigen::Array<bool, Eigen::Dynamic, 1> sampled;
};

// Column `c` of `rows` in SI units as `m` maps it; an empty cell is a gap (not in time), any
// other text an error naming its file:line:column.
MappedColumn ReadColumn(const std::vector<const CsvRow*>& rows, size_t c, const ColumnMapping& m,
                        const std::string& file) {
  const auto nrow = static_cast<Eigen::Index>(rows.size());
  MappedColumn out{Eigen::VectorXd(nrow), Eigen::Array<bool, Eigen::Dynamic, 1>(nrow)};
  for (Eigen::Index i = 0; i < nrow; ++i) {
    const CsvRow& row = *rows[static_cast<size_t>(i)];
    if (c >= row.fields.size())
      throw InputError(Located(file, row.line, row.end_column,
                               "short row: no cell for column '" + m.source + "'"));
    const ParsedNumber p = ParseNumber(row.fields[c].text);
    out.sampled(i) = p.status == NumberStatus::kOk;
    out.values(i) = p.value * m.factor;
    if (p.status == NumberStatus::kEmpty && m.target != "t") continue;
    if (p.status != NumberStatus::kOk)
      throw InputError(Located(
          file, row.line, row.fields[c].column,
          "column '" + m.source + "': " + DescribeNumberStatus(p.status, row.fields[c].text)));
  }
  return out;
}

// The import's first note: rows, separator, and each channel with its column and unit.
std::string ChannelsNote(const std::string& file, size_t rows, char sep,
                         const std::vector<ColumnMapping>& plan) {
  std::ostringstream s;
  s << file << ": " << rows << " rows, separator '" << SeparatorName(sep) << "'; channels:";
  for (const ColumnMapping& m : plan) {
    s << ' ' << m.target;
    if (m.source != m.target || !m.unit.empty()) s << "=" << m.source;
    if (!m.unit.empty()) s << " (" << m.unit << " to SI, x" << m.factor << ")";
  }
  return s.str();
}

// Earth-fixed vn, ve turned to body-fixed u, v with psi; `where` (the header's file:line: )
// introduces the error when one of the three is missing.
void AddBodyVelocities(Dataset& data, const std::string& where) {
  if (!data.Has("vn") || !data.Has("ve") || !data.Has("psi"))
    throw InputError(where + "--map: earth-fixed velocities need all of vn, ve and psi");
  const Channel& vn = data.Get("vn");
  const Channel& ve = data.Get("ve");
  const Channel& psi = data.Get("psi");
  const Eigen::Array<bool, Eigen::Dynamic, 1> both = vn.sampled() && ve.sampled() && psi.sampled();
  BodyVelocities body = EarthToBody(vn.values(), ve.values(), psi.values());
  data.Set("u", std::move(body.u), both);
  data.Set("v", std::move(body.v), both);
}

}  // namespace

Dataset ParseCsvLog(const std::string& text, const std::string& file,
                    const std::vector<ColumnMapping>& map, ImportReport& report) {
  if (text.empty()) throw InputError(Located(file, 0, 0, "the file is empty"));
  const char sep = DetectSeparator(text);
  const CsvTable table = TokenizeCsv(text, file, sep);
  if (table.rows.size() < 2) throw InputError(Located(file, 0, 0, "no data rows"));
  const CsvRow& header = table.rows.front();
  std::map<std::string, size_t> column_of;
  for (size_t c = 0; c < header.fields.size(); ++c) column_of.emplace(header.fields[c].text, c);

  std::vector<ColumnMapping> plan = map;
  if (plan.empty())
    for (const CsvField& f : header.fields) plan.push_back({f.text, f.text, "", 1.0});
  if (std::none_of(plan.begin(), plan.end(), [](const auto& m) { return m.target == "t"; }))
    throw InputError(
        Located(file, header.line, 0, "no time channel: map one with --map t=COLUMN[:unit]"));

  const DataRows rows = RowsWithData(table);
  if (rows.rows.size() < 2) throw InputError(Located(file, 0, 0, "fewer than two rows with data"));
  std::vector<MappedColumn> columns;
  for (const ColumnMapping& m : plan) {
    const auto it = column_of.find(m.source);
    if (it == column_of.end())
      throw InputError(Located(
          file, header.line, 0,
          "--map " + m.target + "=" + m.source + ": no column '" + m.source + "' in the header"));
    columns.push_back(ReadColumn(rows.rows, it->second, m, file));
  }

  Dataset data;
  for (size_t k = 0; k < plan.size(); ++k)
    if (plan[k].target == "t") data = Dataset(columns[k].values);
  for (size_t k = 0; k < plan.size(); ++k)
    if (plan[k].target != "t") data.Set(plan[k].target, columns[k].values, columns[k].sampled);
  data.metadata()["source"] = file;
  data.metadata()["format"] = "csv";

  report.Note(ChannelsNote(file, rows.rows.size(), sep, plan));
  if (rows.empty_rows > 0)
    report.Note("dropped " + std::to_string(rows.empty_rows) +
                " rows with every cell empty (the first at line " +
                std::to_string(rows.first_empty_line) + ")");
  if (data.Has("vn") || data.Has("ve")) {
    AddBodyVelocities(data, Located(file, header.line, 0, ""));
    report.Note("earth-fixed vn, ve rotated to body-fixed u, v with psi");
  }
  report.Note(DropNonIncreasingRows(data).Summary());
  UnwrapHeadings(data, report);
  return data;
}

Dataset ImportCsvLog(const std::string& path, const std::vector<ColumnMapping>& map,
                     ImportReport& report) {
  return ParseCsvLog(ReadTextFile(path), path, map, report);
}

}  // namespace usvid
