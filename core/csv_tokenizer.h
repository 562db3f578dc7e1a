// Splits delimited text into rows of fields, remembering where each field starts, so that every
// later error can say file:line:column. Accepts a UTF-8 byte-order mark, CRLF or LF line ends,
// RFC 4180 double-quoted fields (no line breaks inside), and skips blank lines.
// Throws InputError on bytes that do not belong in a text file (NUL, control characters,
// invalid UTF-8) and on an unterminated quote.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace usvid {

struct CsvField {
  std::string text;
  int column = 0;  // 1-based byte column where the field starts
};

struct CsvRow {
  int line = 0;        // 1-based line number in the file
  int end_column = 0;  // 1-based column just past the last character of the line
  std::vector<CsvField> fields;
};

struct CsvTable {
  std::string file;  // the name used in error messages
  std::vector<CsvRow> rows;
};

// Splits one line (without its line end) into `row`, reusing the row's fields and their text
// storage: a reader that keeps one row allocates nothing per line once it has seen the widest.
void SplitCsvLine(std::string_view line, const std::string& file, int line_no, char separator,
                  CsvRow& row);

// Throws InputError at the first byte that a text file does not hold (NUL, control characters,
// invalid UTF-8), naming file:line:column.
void CheckTextLine(std::string_view line, const std::string& file, int line_no);

// True for a line of nothing but spaces and tabs (readers skip it).
bool IsBlankLine(std::string_view line);

// The lines of a text held in memory, in the order and form TextFileLines gives them.
class TextLines {
 public:
  TextLines(std::string_view text, std::string file);
  // The next line (without its line end, checked by CheckTextLine) and its 1-based number;
  // false at the end. The view lives as long as the text.
  bool Next(std::string_view& line, int& line_no);
  const std::string& file() const { return file_; }
  // Lines in the text: an upper bound for the rows, to size the columns once.
  std::int64_t CountLines() const;
  std::uint64_t bytes_read() const { return pos_; }
  std::uint64_t size() const { return text_.size(); }

 private:
  std::string_view text_;
  std::string file_;
  size_t pos_ = 0;
  int line_no_ = 0;
};

// The lines of a file, read a line at a time through a 1 MiB buffer: the file is never whole in
// memory. A UTF-8 byte-order mark is skipped, CRLF and LF line ends are removed.
class TextFileLines {
 public:
  // Throws InputError when the path is a folder or cannot be opened.
  explicit TextFileLines(const std::string& path);
  bool Next(std::string_view& line, int& line_no);  // the view lives until the next call
  const std::string& file() const { return file_; }
  std::int64_t CountLines() const;  // reads the file once more, in blocks
  std::uint64_t bytes_read() const { return bytes_read_; }
  std::uint64_t size() const { return size_; }

 private:
  std::string file_;
  std::vector<char> buffer_;
  std::ifstream in_;
  std::string line_;
  std::uint64_t size_ = 0, bytes_read_ = 0;
  int line_no_ = 0;
};

CsvTable TokenizeCsv(std::string_view text, const std::string& file, char separator = ',');

// Splits on runs of blanks (spaces and tabs) instead of a separator, after skipping the first
// `header_lines` lines; for column files such as MARIN's .dat.
CsvTable TokenizeWhitespace(std::string_view text, const std::string& file, int header_lines);

// Reads a whole file into memory; throws InputError when it cannot be read or is a directory.
std::string ReadTextFile(const std::string& path);

}  // namespace usvid
