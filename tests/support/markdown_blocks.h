#pragma once
// Reads the commands a Markdown page shows a reader: the fenced ```sh block under a heading, cut
// into the command lines a shell would run (comments and blank lines dropped, `\` continuations
// joined). Tests run those lines as written, so the page cannot drift from what the CLI does.
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace tecido::testing {

inline std::vector<std::string> text_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// The body of the first ```sh block after the heading whose text is `heading` (any level),
/// before the next heading; empty when there is none.
inline std::vector<std::string> sh_block_under(const std::string& markdown, const std::string& heading) {
  const std::vector<std::string> lines = text_lines(markdown);
  std::size_t i = 0;
  auto is_heading = [](const std::string& l) {
    const std::size_t text = l.find_first_not_of('#');
    return text != 0 && text != std::string::npos && l[text] == ' ';
  };
  auto heading_text = [](const std::string& l) { return l.substr(l.find_first_not_of('#') + 1); };
  while (i < lines.size() && !(is_heading(lines[i]) && heading_text(lines[i]) == heading)) ++i;
  for (++i; i < lines.size() && !is_heading(lines[i]); ++i) {
    if (lines[i] != "```sh") continue;
    std::vector<std::string> body;
    for (++i; i < lines.size() && lines[i].rfind("```", 0) != 0; ++i) body.push_back(lines[i]);
    return body;
  }
  return {};
}

/// The commands of a block: `\` continuations joined, blank and comment-only lines dropped.
inline std::vector<std::string> shell_commands(const std::vector<std::string>& block) {
  std::vector<std::string> commands;
  std::string pending;
  for (const std::string& line : block) {
    const bool continues = !line.empty() && line.back() == '\\';
    pending += continues ? line.substr(0, line.size() - 1) : line;
    if (continues) continue;
    const std::size_t first = pending.find_first_not_of(" \t");
    if (first != std::string::npos && pending[first] != '#') commands.push_back(pending);
    pending.clear();
  }
  return commands;
}

/// The exit status a command's trailing comment promises ("# ... exits 1 ..."); 0 when it names none.
inline int promised_exit(const std::string& command) {
  const std::size_t hash = command.find(" #");
  if (hash == std::string::npos) return 0;
  const std::size_t at = command.find("exits ", hash);
  return at == std::string::npos ? 0 : std::atoi(command.c_str() + at + 6);
}

}  // namespace tecido::testing
