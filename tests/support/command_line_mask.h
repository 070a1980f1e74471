#pragma once
// Outputs that must agree byte for byte (two runs at other --threads or --out, a merge against the
// run it merges, a kill-and-rerun) differ in the command line they record
// (comparisons/io/provenance.h). These put a fixed text in its place, after checking that it is
// there, so that the comparison still covers everything else, version and commit included.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace tecido::testing {

inline const std::string kMaskedCommandLine = "<command line>";

/// JSON text (any spacing) with the value of its one "command_line" key replaced.
inline std::string mask_command_line(std::string text) {
  const std::string key = "\"command_line\":";
  const auto at = text.find(key);
  EXPECT_NE(at, std::string::npos) << "no command line recorded: " << text.substr(0, 200);
  if (at == std::string::npos) return text;
  EXPECT_EQ(text.find(key, at + 1), std::string::npos) << "more than one command line";
  auto open = text.find('"', at + key.size());
  auto close = open + 1;
  while (close < text.size() && text[close] != '"') close += text[close] == '\\' ? 2 : 1;
  text.replace(open, close + 1 - open, "\"" + kMaskedCommandLine + "\"");
  return text;
}

/// The parsed report with tecido.command_line replaced.
inline nlohmann::json mask_command_line_json(nlohmann::json j) {
  EXPECT_TRUE(j.contains("tecido") && j["tecido"].contains("command_line")) << "no command line recorded";
  j["tecido"]["command_line"] = kMaskedCommandLine;
  return j;
}

/// report.md with the command line of its provenance line ("tecido V, commit C: `...`") replaced.
inline std::string mask_command_line_md(std::string md) {
  const auto at = md.find(", commit ");
  const auto open = md.find(": `", at);
  const auto end = md.find('\n', open);
  EXPECT_TRUE(at != std::string::npos && open != std::string::npos && end != std::string::npos &&
              md.rfind("\ntecido ", at) != std::string::npos)
      << "no provenance line: " << md.substr(0, 200);
  if (at == std::string::npos || open == std::string::npos || end == std::string::npos) return md;
  md.replace(open, end - open, ": `" + kMaskedCommandLine + "`");
  return md;
}

}  // namespace tecido::testing
