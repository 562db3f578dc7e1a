// Splits delimited text into rows of fields, remembering where each field starts, so that every
// later error can say file:line:column. Accepts a UTF-8 byte-order mark, CRLF or LF line ends,
// RFC 4180 double-quoted fields (no line breaks inside), and skips blank lines.
// Throws InputError on bytes that do not belong in a text file (NUL, control characters,
// invalid UTF-8) and on an unterminated quote.
#pragma once

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

CsvTable TokenizeCsv(std::string_view text, const std::string& file, char separator = ',');

// Splits on runs of blanks (spaces and tabs) instead of a separator, after skipping the first
// `header_lines` lines; for column files such as MARIN's .dat.
CsvTable TokenizeWhitespace(std::string_view text, const std::string& file, int header_lines);

// Reads a whole file into memory; throws InputError when it cannot be read or is a directory.
std::string ReadTextFile(const std::string& path);

}  // namespace usvid
