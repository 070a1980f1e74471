#pragma once
// The relative links of a Markdown page ([text](target) with no scheme) and the anchors its
// headings get when rendered, so a test can hold every link between the README and docs/ to a
// file and a heading that exist: moving a section must not leave a link pointing nowhere.
#include <cctype>
#include <set>
#include <string>
#include <vector>

#include "tests/support/markdown_blocks.h"

namespace tecido::testing {

/// GitHub's anchor of a heading: lower case, spaces to `-`, ASCII punctuation other than `-` and
/// `_` dropped, other characters (accented letters) kept.
inline std::string heading_anchor(const std::string& heading) {
  std::string anchor;
  for (const char c : heading) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80 || std::isalnum(u) || c == '-' || c == '_')
      anchor += static_cast<char>(u < 0x80 ? std::tolower(u) : u);
    else if (c == ' ')
      anchor += '-';
  }
  return anchor;
}

/// The anchors of every heading of a page (outside fenced blocks).
inline std::set<std::string> page_anchors(const std::string& markdown) {
  std::set<std::string> anchors;
  bool fenced = false;
  for (const std::string& line : text_lines(markdown)) {
    if (line.rfind("```", 0) == 0) fenced = !fenced;
    if (fenced || line.empty() || line[0] != '#') continue;
    const std::size_t text = line.find_first_not_of('#');
    if (text != std::string::npos && line[text] == ' ') anchors.insert(heading_anchor(line.substr(text + 1)));
  }
  return anchors;
}

/// The targets of the page's relative links ("docs/engines.md#the-c-plug-in", "#limits"), in order.
inline std::vector<std::string> relative_links(const std::string& markdown) {
  std::vector<std::string> links;
  for (std::size_t at = markdown.find("]("); at != std::string::npos; at = markdown.find("](", at + 2)) {
    const std::size_t end = markdown.find(')', at + 2);
    if (end == std::string::npos) break;
    const std::string target = markdown.substr(at + 2, end - at - 2);
    if (!target.empty() && target.find("://") == std::string::npos && target.find_first_of(" \n") == std::string::npos)
      links.push_back(target);
  }
  return links;
}

}  // namespace tecido::testing
