// The small part of markdown that summary.md uses, as HTML for report.html: `#`..`######`
// headings, paragraphs, `- item` lists and pipe tables (the row above a `| --- |` separator is the
// header, `\|` is a pipe inside a cell), with `**strong**`, `*em*` and `` `code` `` inside any of
// them and the backslash escapes \\ \* \` \| \_. Everything else is HTML-escaped text; this is no
// general markdown engine (no links, nesting, numbered lists or code blocks). Nothing throws.
#pragma once

#include <string>

namespace usvid {

struct MarkdownHtmlOptions {
  // Drop the first `# ` heading (the document title): by default, since the page around the
  // fragment (report.html) writes its own <h1>. `{.skip_title = false}` keeps it as an <h1>.
  bool skip_title = true;
};

// An HTML fragment (no <html> or <body>) for the markdown `md`.
std::string MarkdownToHtml(const std::string& md, const MarkdownHtmlOptions& options = {});

}  // namespace usvid
