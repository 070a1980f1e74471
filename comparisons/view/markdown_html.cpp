#include "comparisons/view/markdown_html.h"

#include "comparisons/view/html_text.h"

#include <cctype>
#include <vector>

namespace tecido::view {

namespace {

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::size_t indent_of(std::string_view line) {
  std::size_t k = 0;
  while (k < line.size() && line[k] == ' ') ++k;
  return k;
}

/// "[text](target)" at s[0]: text, target and the length consumed; false when s does not start one.
bool bracket_link(std::string_view s, std::string_view& text, std::string_view& target, std::size_t& used) {
  if (s.empty() || s[0] != '[') return false;
  int depth = 0;
  std::size_t close = std::string_view::npos;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (s[k] == '[') ++depth;
    if (s[k] == ']' && --depth == 0) {
      close = k;
      break;
    }
  }
  if (close == std::string_view::npos || close + 1 >= s.size() || s[close + 1] != '(') return false;
  const std::size_t end = s.find(')', close + 2);
  if (end == std::string_view::npos) return false;
  text = s.substr(1, close - 1);
  target = s.substr(close + 2, end - close - 2);
  used = end + 1;
  return true;
}

}  // namespace

bool safe_link_target(std::string_view t) {
  if (t.empty()) return false;
  if (starts_with(t, "https://")) return t.find_first_of(" \"'<>\\") == std::string_view::npos;
  if (starts_with(t, "//")) return false;
  for (char c : t) {
    if (c == '/' || c == '#' || c == '?') break;
    if (c == ':') return false;  // a scheme (javascript:, data:, file:, ...)
  }
  return t.find_first_of(" \"'<>\\`") == std::string_view::npos;
}

std::string markdown_inline_html(std::string_view s) {
  std::string out;
  std::size_t k = 0;
  while (k < s.size()) {
    const std::string_view rest = s.substr(k);
    std::string_view text, target;
    std::size_t used = 0;
    if (rest[0] == '`') {
      const std::size_t end = rest.find('`', 1);
      if (end != std::string_view::npos) {
        out += "<code>" + html_text(rest.substr(1, end - 1)) + "</code>";
        k += end + 1;
        continue;
      }
    } else if (starts_with(rest, "**")) {
      const std::size_t end = rest.find("**", 2);
      if (end != std::string_view::npos && end > 2) {
        out += "<strong>" + markdown_inline_html(rest.substr(2, end - 2)) + "</strong>";
        k += end + 2;
        continue;
      }
    } else if (starts_with(rest, "![") && bracket_link(rest.substr(1), text, target, used) && safe_link_target(target)) {
      out += "<img src=\"" + html_text(target) + "\" alt=\"" + html_text(text) + "\">";
      k += used + 1;
      continue;
    } else if (bracket_link(rest, text, target, used) && safe_link_target(target)) {
      out += "<a href=\"" + html_text(target) + "\">" + markdown_inline_html(text) + "</a>";
      k += used;
      continue;
    }
    out += html_text(rest.substr(0, 1));
    ++k;
  }
  return out;
}

namespace {

/// The cells of a table row "| a | b |" ("\|" a literal bar; bars inside `code` are cells' text).
std::vector<std::string> table_cells(std::string_view row) {
  row = trim(row);
  if (starts_with(row, "|")) row.remove_prefix(1);
  if (!row.empty() && row.back() == '|' && (row.size() < 2 || row[row.size() - 2] != '\\')) row.remove_suffix(1);
  std::vector<std::string> cells(1);
  bool in_code = false;
  for (std::size_t k = 0; k < row.size(); ++k) {
    if (row[k] == '\\' && k + 1 < row.size() && row[k + 1] == '|') {
      cells.back() += '|';
      ++k;
    } else if (row[k] == '|' && !in_code) {
      cells.emplace_back();
    } else {
      if (row[k] == '`') in_code = !in_code;
      cells.back() += row[k];
    }
  }
  for (auto& c : cells) c = std::string(trim(c));
  return cells;
}

bool is_rule_row(std::string_view line) {
  line = trim(line);
  if (!starts_with(line, "|")) return false;
  for (char c : line)
    if (c != '|' && c != '-' && c != ':' && c != ' ') return false;
  return line.find('-') != std::string_view::npos;
}

/// "right", "center" or "" per column of the |---:| row.
std::vector<std::string> alignments(std::string_view rule) {
  std::vector<std::string> out;
  for (const std::string& c : table_cells(rule)) {
    const bool l = !c.empty() && c.front() == ':', r = !c.empty() && c.back() == ':';
    out.push_back(l && r ? "center" : r ? "right" : "");
  }
  return out;
}

std::string table_row(const std::vector<std::string>& cells, const std::vector<std::string>& align, const char* tag) {
  std::string out = "<tr>";
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::string& a = c < align.size() ? align[c] : std::string();
    out += std::string("<") + tag + (a == "right" ? " class=\"num\"" : a == "center" ? " class=\"center\"" : "") + ">" +
           markdown_inline_html(cells[c]) + "</" + tag + ">";
  }
  return out + "</tr>\n";
}

/// A list item's marker: the text after "- ", "* " or "N. ", and whether it is ordered.
bool list_item(std::string_view line, std::string_view& text, bool& ordered) {
  line = trim(line);
  if (starts_with(line, "- ") || starts_with(line, "* ")) {
    text = line.substr(2);
    ordered = false;
    return true;
  }
  std::size_t k = 0;
  while (k < line.size() && std::isdigit(static_cast<unsigned char>(line[k]))) ++k;
  if (k > 0 && k + 1 < line.size() && line[k] == '.' && line[k + 1] == ' ') {
    text = line.substr(k + 2);
    ordered = true;
    return true;
  }
  return false;
}

int heading_level(std::string_view line) {
  int level = 0;
  while (level < static_cast<int>(line.size()) && line[level] == '#') ++level;
  return (level >= 1 && level <= 6 && static_cast<int>(line.size()) > level && line[level] == ' ') ? level : 0;
}

class Converter {
 public:
  explicit Converter(std::string_view md) {
    std::size_t start = 0;
    while (start <= md.size()) {
      const std::size_t end = md.find('\n', start);
      lines_.push_back(md.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
      if (end == std::string_view::npos) break;
      start = end + 1;
    }
  }

  std::string run() {
    while (k_ < lines_.size()) block();
    return out_;
  }

 private:
  std::vector<std::string_view> lines_;
  std::size_t k_ = 0;
  std::string out_;

  void block() {
    const std::string_view line = lines_[k_];
    std::string_view text;
    bool ordered = false;
    if (trim(line).empty()) {
      ++k_;
    } else if (starts_with(trim(line), "```")) {
      code_block();
    } else if (const int h = heading_level(line)) {
      const std::string n = std::to_string(h);
      out_ += "<h" + n + ">" + markdown_inline_html(trim(line.substr(h + 1))) + "</h" + n + ">\n";
      ++k_;
    } else if (starts_with(trim(line), "|") && k_ + 1 < lines_.size() && is_rule_row(lines_[k_ + 1])) {
      table();
    } else if (list_item(line, text, ordered)) {
      list(indent_of(line));
    } else {
      paragraph();
    }
  }

  void code_block() {
    ++k_;
    out_ += "<pre><code>";
    while (k_ < lines_.size() && !starts_with(trim(lines_[k_]), "```")) out_ += html_text(lines_[k_++]) + "\n";
    if (k_ < lines_.size()) ++k_;
    out_ += "</code></pre>\n";
  }

  void table() {
    const std::vector<std::string> align = alignments(lines_[k_ + 1]);
    out_ += "<table>\n<thead>" + table_row(table_cells(lines_[k_]), align, "th") + "</thead>\n<tbody>\n";
    k_ += 2;
    while (k_ < lines_.size() && starts_with(trim(lines_[k_]), "|")) out_ += table_row(table_cells(lines_[k_++]), align, "td");
    out_ += "</tbody>\n</table>\n";
  }

  /// Items at this indent; deeper items become a nested list inside the item before them;
  /// indented lines that are no item continue the item's text.
  void list(std::size_t indent) {
    std::string_view text;
    bool ordered = false;
    list_item(lines_[k_], text, ordered);
    const char* tag = ordered ? "ol" : "ul";
    out_ += std::string("<") + tag + ">\n";
    bool open = false;
    while (k_ < lines_.size() && !trim(lines_[k_]).empty()) {
      const std::string_view line = lines_[k_];
      const std::size_t in = indent_of(line);
      const bool item = list_item(line, text, ordered);
      if (item && in < indent) break;
      if (item && in > indent) {
        list(in);
        continue;
      }
      if (item) {
        if (open) out_ += "</li>\n";
        out_ += "<li>" + markdown_inline_html(text);
        open = true;
      } else if (in > 0 && open) {
        out_ += " " + markdown_inline_html(trim(line));
      } else {
        break;
      }
      ++k_;
    }
    if (open) out_ += "</li>\n";
    out_ += std::string("</") + tag + ">\n";
  }

  void paragraph() {
    std::string text;
    std::string_view item;
    bool ordered = false;
    while (k_ < lines_.size()) {
      const std::string_view line = lines_[k_];
      if (trim(line).empty() || heading_level(line) || starts_with(trim(line), "```") ||
          (!text.empty() && (list_item(line, item, ordered) || starts_with(trim(line), "|"))))
        break;
      if (!text.empty()) text += ' ';
      text += std::string(trim(line));
      ++k_;
    }
    out_ += "<p>" + markdown_inline_html(text) + "</p>\n";
  }
};

}  // namespace

std::string markdown_html(std::string_view markdown) { return Converter(markdown).run(); }

}  // namespace tecido::view
