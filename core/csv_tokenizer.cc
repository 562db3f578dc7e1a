#include "core/csv_tokenizer.h"

#include <algorithm>
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

}  // namespace

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

void SplitCsvLine(std::string_view line, const std::string& file, int line_no, char separator,
                  CsvRow& row) {
  row.line = line_no;
  row.end_column = static_cast<int>(line.size()) + 1;
  size_t count = 0;
  auto next_field = [&](int column) -> CsvField& {
    if (row.fields.size() <= count) row.fields.emplace_back();
    CsvField& field = row.fields[count++];
    field.column = column;
    field.text.clear();
    return field;
  };
  size_t i = 0;
  while (true) {
    CsvField& field = next_field(static_cast<int>(i) + 1);
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
      field.text.assign(line.substr(i, end == std::string_view::npos ? end : end - i));
      i = end == std::string_view::npos ? line.size() : end;
    }
    if (i >= line.size()) break;
    ++i;  // skip the separator; a trailing separator makes one more (empty) field
    if (i == line.size()) {
      next_field(static_cast<int>(i) + 1);
      break;
    }
  }
  row.fields.resize(count);
}

namespace {

// Calls visit(line, line_no) for every line after a BOM, with its line end removed.
template <typename Visit>
void ForEachLine(std::string_view text, const std::string& file, Visit visit) {
  TextLines lines(text, file);
  std::string_view line;
  int line_no = 0;
  while (lines.Next(line, line_no)) visit(line, line_no);
}

// A line as split from the text: the byte-order mark of the first removed, and a CR line end;
// then checked (CheckTextLine).
void FinishLine(std::string_view& line, int line_no, const std::string& file) {
  if (line_no == 1 && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  CheckTextLine(line, file, line_no);
}

}  // namespace

bool IsBlankLine(std::string_view line) {
  return line.find_first_not_of(" \t") == std::string_view::npos;
}

CsvTable TokenizeCsv(std::string_view text, const std::string& file, char separator) {
  CsvTable table;
  table.file = file;
  ForEachLine(text, file, [&](std::string_view line, int line_no) {
    if (IsBlankLine(line)) return;
    table.rows.emplace_back();
    SplitCsvLine(line, file, line_no, separator, table.rows.back());
  });
  return table;
}

CsvTable TokenizeWhitespace(std::string_view text, const std::string& file, int header_lines) {
  CsvTable table;
  table.file = file;
  ForEachLine(text, file, [&](std::string_view line, int line_no) {
    if (line_no <= header_lines || IsBlankLine(line)) return;
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

TextLines::TextLines(std::string_view text, std::string file)
    : text_(text), file_(std::move(file)) {}

bool TextLines::Next(std::string_view& line, int& line_no) {
  if (pos_ >= text_.size()) return false;
  size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) end = text_.size();
  line = text_.substr(pos_, end - pos_);
  pos_ = std::min(end + 1, text_.size());
  line_no = ++line_no_;
  FinishLine(line, line_no, file_);
  return true;
}

std::int64_t TextLines::CountLines() const {
  const auto breaks = std::count(text_.begin(), text_.end(), '\n');
  return breaks + (!text_.empty() && text_.back() != '\n' ? 1 : 0);
}

TextFileLines::TextFileLines(const std::string& path) : file_(path), buffer_(1 << 20) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": is a directory, not a file");
  in_.rdbuf()->pubsetbuf(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  in_.open(path, std::ios::binary);
  if (!in_) throw InputError(path + ": cannot open file for reading");
  const auto size = std::filesystem::file_size(path, ec);
  size_ = ec ? 0 : size;
}

bool TextFileLines::Next(std::string_view& line, int& line_no) {
  if (!std::getline(in_, line_)) {
    if (in_.bad()) throw InputError(file_ + ": read error");
    return false;
  }
  bytes_read_ += line_.size() + 1;
  line = line_;
  line_no = ++line_no_;
  FinishLine(line, line_no, file_);
  return true;
}

std::int64_t TextFileLines::CountLines() const {
  std::ifstream in(file_, std::ios::binary);
  std::vector<char> block(1 << 20);
  std::int64_t breaks = 0;
  char last = '\n';
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const auto got = static_cast<size_t>(in.gcount());
    if (got == 0) break;
    breaks += std::count(block.data(), block.data() + got, '\n');
    last = block[got - 1];
  }
  return breaks + (last != '\n' ? 1 : 0);
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
