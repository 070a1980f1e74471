#pragma once
/// The Markdown the suites write (report.md's sections) as HTML, for report.html: a small, strict
/// subset, everything else shown as text.
///  - blocks: ATX headings (# .. ######), paragraphs, lists ("- ", "* ", "N. "; an indented item
///    is a nested list), tables (a header row, the |---|:--:| row, body rows; "\|" is a literal
///    bar in a cell), fenced code (```);
///  - inline: `code`, **bold**, [text](target), ![alt](image). A target is used only when it is a
///    relative path or an anchor (no scheme, no "//") or an https:// address; any other target
///    leaves the link as text.
/// Every character of the input reaches the page through html_text (html_text.h): raw HTML in the
/// Markdown is shown, never interpreted.
#include <string>
#include <string_view>

namespace tecido::view {

std::string markdown_html(std::string_view markdown);

/// The inline part alone (one line of text, no block structure).
std::string markdown_inline_html(std::string_view text);

/// Whether `target` may be a link's or an image's address (the rule above).
bool safe_link_target(std::string_view target);

}  // namespace tecido::view
