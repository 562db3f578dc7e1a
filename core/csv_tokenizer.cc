#include "core/csv_tokenizer.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace usvid {
namespace {

// Length of the UTF-8 sequence starting at s[i], or 0 when it is not valid UTF-8.
int Utf8SequenceLength(std::string_view s, size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  int n = 0;
  if (c < 0x80) return 1;
  if ((c & 0xE0) == 0xC0 && c >= 0xC2)
    n = 2;
  else if ((c & 0xF0) == 0xE0)
    n = 3;
  else if ((c & 0xF8) == 0xF0 && c <= 0xF4)
    n = 4;
  else
    return 0;
  if (i + n > s.size()) return 0;
  for (int k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
  return n;
}

std::string HexByte(unsigned char c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02X", c);
  return buf;
}

// Checks one line (without its line end) for bytes a text file does not hold.
void CheckTextLine(std::string_view line, const std::string& file, int line_no) {
  for (size_t i = 0; i < line.size();) {
    const auto c = static_cast<unsigned char>(line[i]);
    if ((c < 0x20 && c != '\t') || c == 0x7F)
      throw InputError(Located(file, line_no, static_cast<int>(i) + 1,
                               "binary byte " + HexByte(c) + " in a text file"));
    const int n = Utf8SequenceLength(line, i);
    if (n == 0)
      throw InputError(Located(file, line_no, static_cast<int>(i) + 1,
                               "byte " + HexByte(c) + " is not valid UTF-8 text"));
    i += n;
  }
}

CsvRow SplitLine(std::string_view line, const std::string& file, int line_no, char separator) {
  CsvRow row;
  row.line = line_no;
  row.end_column = static_cast<int>(line.size()) + 1;
  size_t i = 0;
  while (true) {
    CsvField field;
    field.column = static_cast<int>(i) + 1;
    size_t start = i;
    while (start < line.size() && line[start] == ' ') ++start;
    if (start < line.size() && line[start] == '"') {
      size_t j = start + 1;
      while (true) {
        if (j >= line.size())
          throw InputError(
              Located(file, line_no, static_cast<int>(start) + 1, "unterminated quoted field"));
        if (line[j] == '"') {
          if (j + 1 < line.size() && line[j + 1] == '"') {
            field.text += '"';
            j += 2;
            continue;
          }
          ++j;
          break;
        }
        field.text += line[j++];
      }
      while (j < line.size() && line[j] == ' ') ++j;
      if (j < line.size() && line[j] != separator)
        throw InputError(Located(file, line_no, static_cast<int>(j) + 1,
                                 "text after the closing quote of a field"));
      i = j;
    } else {
      const size_t end = line.find(separator, i);
      field.text = std::string(line.substr(i, end == std::string_view::npos ? end : end - i));
      i = end == std::string_view::npos ? line.size() : end;
    }
    row.fields.push_back(std::move(field));
    if (i >= line.size()) break;
    ++i;  // skip the separator; a trailing separator makes one more (empty) field
    if (i == line.size()) {
      row.fields.push_back({"", static_cast<int>(i) + 1});
      break;
    }
  }
  return row;
}

// Calls visit(line, line_no) for every line after a BOM, with its line end removed.
template <typename Visit>
void ForEachLine(std::string_view text, const std::string& file, Visit visit) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  int line_no = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    ++line_no;
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    CheckTextLine(line, file, line_no);
    visit(line, line_no);
  }
}

bool IsBlank(std::string_view line) {
  return line.find_first_not_of(" \t") == std::string_view::npos;
}

}  // namespace

CsvTable TokenizeCsv(std::string_view text, const std::string& file, char separator) {
  CsvTable table;
  table.file = file;
  ForEachLine(text, file, [&](std::string_view line, int line_no) {
    if (!IsBlank(line)) table.rows.push_back(SplitLine(line, file, line_no, separator));
  });
  return table;
}

CsvTable TokenizeWhitespace(std::string_view text, const std::string& file, int header_lines) {
  CsvTable table;
  table.file = file;
  ForEachLine(text, file, [&](std::string_view line, int line_no) {
    if (line_no <= header_lines || IsBlank(line)) return;
    CsvRow row;
    row.line = line_no;
    row.end_column = static_cast<int>(line.size()) + 1;
    size_t i = 0;
    while (true) {
      i = line.find_first_not_of(" \t", i);
      if (i == std::string_view::npos) break;
      const size_t end = std::min(line.find_first_of(" \t", i), line.size());
      row.fields.push_back({std::string(line.substr(i, end - i)), static_cast<int>(i) + 1});
      i = end;
    }
    table.rows.push_back(std::move(row));
  });
  return table;
}

std::string ReadTextFile(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw InputError(path + ": read error");
  return ss.str();
}

}  // namespace usvid
