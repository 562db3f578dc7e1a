#include "core/csv_dataset.h"

#include <set>

#include "core/atomic_file.h"
#include "core/csv_tokenizer.h"
#include "core/error.h"
#include "core/parse_number.h"

namespace usvid {
namespace {

void CheckHeader(const CsvTable& table) {
  const CsvRow& header = table.rows.front();
  if (header.fields.size() == 1) {
    for (char sep : {';', '\t', '|'}) {
      const auto at = header.fields[0].text.find(sep);
      if (at != std::string::npos) {
        const std::string name = sep == '\t' ? "a tab" : std::string("'") + sep + "'";
        throw InputError(Located(
            table.file, header.line, static_cast<int>(at) + 1,
            "wrong separator: found " + name + " in the header; data files are comma-separated"));
      }
    }
  }
  std::set<std::string> seen;
  for (const CsvField& f : header.fields) {
    if (f.text.empty())
      throw InputError(Located(table.file, header.line, f.column, "empty column name"));
    if (!seen.insert(f.text).second)
      throw InputError(
          Located(table.file, header.line, f.column, "column '" + f.text + "' appears twice"));
  }
  if (!seen.contains("t"))
    throw InputError(Located(table.file, header.line, 1, "no column 't' (time in seconds)"));
}

}  // namespace

Dataset ParseDatasetCsv(std::string_view text, const std::string& file) {
  if (text.empty()) throw InputError(Located(file, 0, 0, "the file is empty"));
  const CsvTable table = TokenizeCsv(text, file);
  if (table.rows.empty()) throw InputError(Located(file, 0, 0, "the file holds no text"));
  CheckHeader(table);
  if (table.rows.size() == 1)
    throw InputError(Located(file, table.rows[0].line, 0, "header only, no data rows"));

  const CsvRow& header = table.rows.front();
  const size_t ncol = header.fields.size();
  const auto nrow = static_cast<Eigen::Index>(table.rows.size() - 1);
  size_t t_col = 0;
  while (header.fields[t_col].text != "t") ++t_col;

  Eigen::MatrixXd values(nrow, ncol);
  Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic> sampled(nrow, ncol);
  for (Eigen::Index i = 0; i < nrow; ++i) {
    const CsvRow& row = table.rows[i + 1];
    if (row.fields.size() != ncol) {
      const bool shorter = row.fields.size() < ncol;
      const int column = shorter ? row.end_column : row.fields[ncol].column;
      throw InputError(Located(file, row.line, column,
                               std::string(shorter ? "short" : "long") +
                                   " row: " + std::to_string(row.fields.size()) +
                                   " cells, the header has " + std::to_string(ncol)));
    }
    for (size_t c = 0; c < ncol; ++c) {
      const CsvField& f = row.fields[c];
      const ParsedNumber p = ParseNumber(f.text);
      const bool is_time = c == t_col;
      if (p.status == NumberStatus::kEmpty && !is_time) {
        sampled(i, c) = false;
        values(i, c) = 0.0;
        continue;
      }
      if (p.status != NumberStatus::kOk)
        throw InputError(Located(
            file, row.line, f.column,
            "column '" + header.fields[c].text + "': " + DescribeNumberStatus(p.status, f.text)));
      sampled(i, c) = true;
      values(i, c) = p.value;
    }
    if (i > 0 && values(i, t_col) <= values(i - 1, t_col)) {
      const bool equal = values(i, t_col) == values(i - 1, t_col);
      throw InputError(Located(
          file, row.line, row.fields[t_col].column,
          "t = " + FormatNumber(values(i, t_col)) + (equal ? " repeats" : " goes back from") +
              " the previous t = " + FormatNumber(values(i - 1, t_col)) +
              "; t must be strictly increasing (usvid import repairs such logs)"));
    }
  }

  Dataset data(values.col(t_col));
  for (size_t c = 0; c < ncol; ++c)
    if (c != t_col) data.Set(header.fields[c].text, values.col(c), sampled.col(c));
  data.metadata()["source"] = file;
  return data;
}

Dataset ReadDatasetCsv(const std::string& path) {
  return ParseDatasetCsv(ReadTextFile(path), path);
}

std::string FormatDatasetCsv(const Dataset& data) {
  std::string out = "t";
  for (const Channel& c : data.channels()) out += "," + c.name;
  out += '\n';
  for (Eigen::Index i = 0; i < data.rows(); ++i) {
    out += FormatNumber(data.t()(i));
    for (const Channel& c : data.channels()) {
      out += ',';
      if (c.sampled(i)) out += FormatNumber(c.values(i));
    }
    out += '\n';
  }
  return out;
}

void WriteDatasetCsv(const std::string& path, const Dataset& data) {
  WriteFileAtomically(path, FormatDatasetCsv(data));
}

}  // namespace usvid
