#pragma once
// The bad-usage contract (docs/design.md section 3) as assertions on a CLI result: exit 2, nothing
// on stdout, exactly one line on stderr, "tecido: " and the words that name the option, the file
// and pointer, or the path. And a runner for shell set-ups cli_runner.h does not cover (a resource
// limit, stdout to /dev/full).
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <string>

namespace tecido::testing {

inline void expect_rejected(const CliResult& r, std::initializer_list<std::string> needles, const std::string& label) {
  EXPECT_EQ(r.code, 2) << label << ": " << r.err;
  EXPECT_TRUE(r.out.empty()) << label << ": stdout: " << r.out.substr(0, 200);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << label << ": " << r.err;
  EXPECT_EQ(r.err.rfind("tecido: ", 0), 0u) << label << ": " << r.err;
  for (const auto& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << label << ": wanted \"" << n << "\" in " << r.err;
}

/// Runs `sh -c "<setup>; exec TECIDO_CLI <args> <redirects>"`; stderr is captured, stdout too
/// unless `stdout_to` names a file to send it to.
inline CliResult run_cli_with(const std::string& setup, const std::string& args, const std::string& stdout_to = "") {
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path();
  const std::string tag = std::to_string(::getpid()) + "-w" + std::to_string(counter++);
  const auto out = dir / ("tecido-cli-" + tag + ".out"), err = dir / ("tecido-cli-" + tag + ".err");
  const std::string target = stdout_to.empty() ? out.string() : stdout_to;
  const std::string inner = setup + "; exec '" + std::string(TECIDO_CLI) + "' " + args + " >'" + target + "' 2>'" + err.string() + "'";
  std::string quoted = "'";
  for (char c : inner) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  quoted += "'";
  const int status = std::system(("sh -c " + quoted).c_str());
  CliResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = stdout_to.empty() ? slurp(out) : "";
  r.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

/// Every file under `dir` (recursively) whose name contains `part`, e.g. ".tmp." leftovers.
inline std::vector<std::string> files_named(const std::filesystem::path& dir, const std::string& part) {
  std::vector<std::string> out;
  std::error_code ec;
  if (!std::filesystem::exists(dir, ec)) return out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir, ec))
    if (e.path().filename().string().find(part) != std::string::npos) out.push_back(e.path().string());
  return out;
}

}  // namespace tecido::testing
