#include "harness/markdown_html.h"

#include <sstream>
#include <string_view>
#include <vector>

#include "plot/svg_text.h"

namespace usvid {
namespace {

std::string_view Trim(std::string_view s) {
  const size_t begin = s.find_first_not_of(" \t\r");
  if (begin == std::string_view::npos) return {};
  return s.substr(begin, s.find_last_not_of(" \t\r") - begin + 1);
}

bool Escapable(char c) { return std::string_view("\\*`|_").find(c) != std::string_view::npos; }

// Inline markdown of one block: code spans are literal, strong and em may hold other markup.
std::string Inline(std::string_view text) {
  std::string out, plain;
  auto flush = [&] {
    out += svg::Escape(plain);
    plain.clear();
  };
  for (size_t i = 0; i < text.size();) {
    const std::string_view rest = text.substr(i);
    if (rest.size() > 1 && rest[0] == '\\' && Escapable(rest[1])) {
      plain += rest[1];
      i += 2;
      continue;
    }
    if (rest[0] == '`') {
      const size_t close = rest.find('`', 1);
      if (close != std::string_view::npos) {
        flush();
        out += "<code>" + svg::Escape(rest.substr(1, close - 1)) + "</code>";
        i += close + 1;
        continue;
      }
    }
    if (rest.starts_with("**")) {
      const size_t close = rest.find("**", 2);
      if (close != std::string_view::npos && close > 2) {
        flush();
        out += "<strong>" + Inline(rest.substr(2, close - 2)) + "</strong>";
        i += close + 2;
        continue;
      }
    }
    // `*em*` only when the stars hug the text, so "a * b" stays a product.
    if (rest[0] == '*' && rest.size() > 2 && rest[1] != ' ' && rest[1] != '*') {
      const size_t close = rest.find('*', 2);
      if (close != std::string_view::npos && rest[close - 1] != ' ') {
        flush();
        out += "<em>" + Inline(rest.substr(1, close - 1)) + "</em>";
        i += close + 1;
        continue;
      }
    }
    plain += rest[0];
    ++i;
  }
  flush();
  return out;
}

bool IsTableRow(std::string_view line) { return line.starts_with('|'); }

// The cells of `| a | b \| c |`, trimmed; `\|` becomes a pipe inside its cell.
std::vector<std::string> Cells(std::string_view row) {
  row.remove_prefix(1);
  if (row.ends_with('|') && !row.ends_with("\\|")) row.remove_suffix(1);
  std::vector<std::string> cells(1);
  for (size_t i = 0; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size() && row[i + 1] == '|') {
      cells.back() += '|';
      ++i;
    } else if (row[i] == '|') {
      cells.emplace_back();
    } else {
      cells.back() += row[i];
    }
  }
  for (std::string& c : cells) c = std::string(Trim(c));
  return cells;
}

// `| --- | :---: |`: every cell dashes, optionally with alignment colons.
bool IsSeparator(std::string_view line) {
  for (const std::string& cell : Cells(line)) {
    std::string_view c = cell;
    if (c.starts_with(':')) c.remove_prefix(1);
    if (c.ends_with(':')) c.remove_suffix(1);
    if (c.empty() || c.find_first_not_of('-') != std::string_view::npos) return false;
  }
  return true;
}

void AppendRow(std::string_view row, const char* tag, std::string& out) {
  out += "<tr>";
  for (const std::string& cell : Cells(row))
    out += std::string("<") + tag + ">" + Inline(cell) + "</" + tag + ">";
  out += "</tr>\n";
}

// 1 to 6 for a `#`..`######` heading line, else 0.
int HeadingLevel(std::string_view line) {
  const size_t hashes = line.find_first_not_of('#');
  if (hashes < 1 || hashes > 6 || line[hashes] != ' ') return 0;
  return static_cast<int>(hashes);
}

bool IsListItem(std::string_view line) { return line.starts_with("- "); }

}  // namespace

std::string MarkdownToHtml(const std::string& md, const MarkdownHtmlOptions& options) {
  std::vector<std::string> lines;
  std::istringstream in(md);
  for (std::string line; std::getline(in, line);) lines.emplace_back(Trim(line));

  std::string out;
  bool skip_title = options.skip_title;
  for (size_t i = 0; i < lines.size();) {
    const std::string& line = lines[i];
    if (line.empty()) {
      ++i;
    } else if (IsTableRow(line)) {
      out += "<table>\n";
      if (i + 1 < lines.size() && IsTableRow(lines[i + 1]) && IsSeparator(lines[i + 1])) {
        out += "<thead>\n";
        AppendRow(line, "th", out);
        out += "</thead>\n";
        i += 2;
      }
      out += "<tbody>\n";
      for (; i < lines.size() && IsTableRow(lines[i]); ++i)
        if (!IsSeparator(lines[i])) AppendRow(lines[i], "td", out);
      out += "</tbody>\n</table>\n";
    } else if (IsListItem(line)) {
      out += "<ul>\n";
      for (; i < lines.size() && IsListItem(lines[i]); ++i)
        out += "<li>" + Inline(Trim(std::string_view(lines[i]).substr(2))) + "</li>\n";
      out += "</ul>\n";
    } else if (const int level = HeadingLevel(line); level > 0) {
      if (level == 1 && skip_title) {
        skip_title = false;
      } else {
        const std::string h = "h" + std::to_string(level);
        out +=
            "<" + h + ">" + Inline(Trim(std::string_view(line).substr(level))) + "</" + h + ">\n";
      }
      ++i;
    } else {
      // A paragraph runs to the next blank line or the next other block.
      std::string text = line;
      for (++i; i < lines.size() && !lines[i].empty() && !IsTableRow(lines[i]) &&
                !IsListItem(lines[i]) && HeadingLevel(lines[i]) == 0;
           ++i)
        text += "\n" + lines[i];
      out += "<p>" + Inline(text) + "</p>\n";
    }
  }
  return out;
}

}  // namespace usvid
