#include "core/csv_dataset.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>

#include "core/atomic_file.h"
#include "core/csv_tokenizer.h"
#include "core/error.h"
#include "core/json_file.h"
#include "core/parse_number.h"

namespace usvid {
namespace {

void CheckHeader(const CsvRow& header, const std::string& file) {
  if (header.fields.size() == 1) {
    for (char sep : {';', '\t', '|'}) {
      const auto at = header.fields[0].text.find(sep);
      if (at != std::string::npos) {
        const std::string name = sep == '\t' ? "a tab" : std::string("'") + sep + "'";
        throw InputError(Located(
            file, header.line, static_cast<int>(at) + 1,
            "wrong separator: found " + name + " in the header; data files are comma-separated"));
      }
    }
  }
  std::set<std::string> seen;
  for (const CsvField& f : header.fields) {
    if (f.text.empty()) throw InputError(Located(file, header.line, f.column, "empty column name"));
    if (!seen.insert(f.text).second)
      throw InputError(
          Located(file, header.line, f.column, "column '" + f.text + "' appears twice"));
  }
  if (!seen.contains("t"))
    throw InputError(Located(file, header.line, 1, "no column 't' (time in seconds)"));
}

// One column while it is read: its values and mask, sized once for every line of the file.
// A column whose first value is not a number is text: its storage is freed, its later cells are
// not parsed, and it keeps where its first text stood.
struct ColumnBuilder {
  std::string name;
  Eigen::VectorXd values;
  Eigen::Array<bool, Eigen::Dynamic, 1> sampled;
  bool numeric = false;                     // a number seen
  std::optional<Dataset::TextColumn> text;  // set: a text column
};

void ReportProgress(const CsvReadOptions& options, std::uint64_t done, std::uint64_t total,
                    Eigen::Index rows, std::uint64_t& next) {
  if (!options.progress || done < next || done >= total) return;  // the end is reported once
  options.progress(static_cast<double>(done) / static_cast<double>(total), rows);
  next = done + total / 10;
}

// A row of as many cells as the header, else an error at its first missing or extra cell.
void CheckRowWidth(const CsvRow& row, size_t ncol, const std::string& file) {
  if (row.fields.size() == ncol) return;
  const bool shorter = row.fields.size() < ncol;
  const int column = shorter ? row.end_column : row.fields[ncol].column;
  throw InputError(Located(file, row.line, column,
                           std::string(shorter ? "short" : "long") +
                               " row: " + std::to_string(row.fields.size()) +
                               " cells, the header has " + std::to_string(ncol)));
}

// Cell `f` of row `row` into row n of its column: a number, a gap (empty, not in t), or the
// first text of a column that has held no number yet (a text column: a mode, a comment, refused
// only by a command that needs it as a number, Dataset::Get); anything else is an error.
void ReadCell(ColumnBuilder& col, const CsvField& f, const CsvRow& row, Eigen::Index n,
              bool is_time, const std::string& file) {
  const ParsedNumber p = ParseNumber(f.text);
  if (p.status == NumberStatus::kEmpty && !is_time) {
    col.sampled(n) = false;
    col.values(n) = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  if (p.status != NumberStatus::kOk) {
    if (p.status == NumberStatus::kNotANumber && !col.numeric && !is_time) {
      const std::string where =
          file + ":" + std::to_string(row.line) + ":" + std::to_string(f.column);
      col.text = Dataset::TextColumn{col.name, where, f.text};
      col.values = Eigen::VectorXd();
      col.sampled = Eigen::Array<bool, Eigen::Dynamic, 1>();
      return;
    }
    throw InputError(
        Located(file, row.line, f.column,
                "column '" + col.name + "': " + DescribeNumberStatus(p.status, f.text)));
  }
  col.numeric = true;
  col.sampled(n) = true;
  col.values(n) = p.value;
}

// t at row n after row n - 1, else an error naming both.
void CheckTimeIncreases(const Eigen::VectorXd& t, Eigen::Index n, const CsvRow& row, int column,
                        const std::string& file) {
  if (n == 0 || t(n) > t(n - 1)) return;
  const bool equal = t(n) == t(n - 1);
  throw InputError(Located(file, row.line, column,
                           "t = " + FormatNumber(t(n)) + (equal ? " repeats" : " goes back from") +
                               " the previous t = " + FormatNumber(t(n - 1)) +
                               "; t must be strictly increasing (usvid import repairs such logs)"));
}

// The columns' first n rows as a dataset on t (column t_col).
Dataset Assemble(std::vector<ColumnBuilder>& columns, size_t t_col, Eigen::Index n,
                 const std::string& file) {
  ColumnBuilder& time = columns[t_col];
  time.values.conservativeResize(n);
  Dataset data(std::move(time.values));
  for (size_t c = 0; c < columns.size(); ++c) {
    ColumnBuilder& col = columns[c];
    if (c == t_col) continue;
    if (col.text) {
      data.AddTextColumn(std::move(*col.text));
      continue;
    }
    col.values.conservativeResize(n);
    col.sampled.conservativeResize(n);
    data.Set(col.name, std::move(col.values), std::move(col.sampled));
  }
  data.metadata()["source"] = file;
  return data;
}

template <typename Lines>
Dataset ParseLines(Lines& lines, const CsvReadOptions& options) {
  const std::string& file = lines.file();
  if (lines.size() == 0) throw InputError(Located(file, 0, 0, "the file is empty"));
  std::string_view line;
  int line_no = 0;
  CsvRow row;
  auto next_row = [&] {
    while (lines.Next(line, line_no)) {
      if (IsBlankLine(line)) continue;
      SplitCsvLine(line, file, line_no, ',', row);
      return true;
    }
    return false;
  };
  if (!next_row()) throw InputError(Located(file, 0, 0, "the file holds no text"));
  CheckHeader(row, file);
  const CsvRow header = row;
  const size_t ncol = header.fields.size();
  size_t t_col = 0;
  while (header.fields[t_col].text != "t") ++t_col;

  // Every line but the header may be a row: the columns are sized once and trimmed at the end.
  const Eigen::Index capacity = std::max<std::int64_t>(lines.CountLines() - header.line, 0);
  std::vector<ColumnBuilder> columns(ncol);
  for (size_t c = 0; c < ncol; ++c) {
    columns[c].name = header.fields[c].text;
    columns[c].values.resize(capacity);
    columns[c].sampled.resize(capacity);
  }
  Eigen::Index n = 0;
  std::uint64_t next_progress = lines.size() / 10;
  while (next_row()) {
    CheckRowWidth(row, ncol, file);
    if (n >= capacity)  // a log still being written
      throw InputError(Located(file, row.line, 0, "the file grew while it was read"));
    for (size_t c = 0; c < ncol; ++c)
      if (!columns[c].text) ReadCell(columns[c], row.fields[c], row, n, c == t_col, file);
    CheckTimeIncreases(columns[t_col].values, n, row, row.fields[t_col].column, file);
    ++n;
    ReportProgress(options, lines.bytes_read(), lines.size(), n, next_progress);
  }
  if (n == 0) throw InputError(Located(file, header.line, 0, "header only, no data rows"));
  if (options.progress) options.progress(1.0, n);
  return Assemble(columns, t_col, n, file);
}

}  // namespace

Dataset ParseDatasetCsv(std::string_view text, const std::string& file) {
  TextLines lines(text, file);
  return ParseLines(lines, {});
}

Dataset ReadDatasetCsv(const std::string& path, const CsvReadOptions& options) {
  TextFileLines lines(path);
  Dataset data = ParseLines(lines, options);
  const std::string record = RecordJsonPath(path);
  std::error_code ec;
  if (std::filesystem::exists(record, ec)) {
    const nlohmann::json j = ReadJsonFile(record);
    const auto maneuver = j.is_object() ? j.find("maneuver") : j.end();
    if (!j.is_object() || maneuver == j.end() || !maneuver->is_string() ||
        maneuver->get<std::string>().empty())
      throw InputError(record + ": the record file of " + path +
                       " must be a JSON object with a non-empty string \"maneuver\"");
    data.metadata()["maneuver"] = maneuver->get<std::string>();
  }
  return data;
}

std::string RecordJsonPath(const std::string& data_path) {
  const auto dot = data_path.rfind('.');
  const auto slash = data_path.rfind('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_ext ? data_path.substr(0, dot) : data_path) + ".record.json";
}

std::string FormatDatasetCsv(const Dataset& data) {
  std::string out = "t";
  for (const Channel& c : data.channels()) out += "," + c.name;
  out += '\n';
  for (Eigen::Index i = 0; i < data.rows(); ++i) {
    out += FormatNumber(data.t()(i));
    for (const Channel& c : data.channels()) {
      out += ',';
      if (c.IsSampled(i)) out += FormatNumber(c.Value(i));
    }
    out += '\n';
  }
  return out;
}

void WriteDatasetCsv(const std::string& path, const Dataset& data) {
  WriteFileAtomically(path, FormatDatasetCsv(data));
}

}  // namespace usvid
