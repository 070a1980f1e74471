// What every output says about how it was made (comparisons/io/provenance.h): the version is the
// CMake project's, the commit git's own answer for this checkout (or "unknown"), and the command
// line is quoted so that a shell runs it again as it was.
#include "comparisons/io/source_dir.h"
#include "comparisons/io/provenance.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <regex>

namespace tecido {
namespace {

/// The VERSION of project(tecido ...) in the top CMakeLists.txt, read here independently.
std::string cmake_project_version() {
  const std::string text = testing::slurp(std::filesystem::path(TECIDO_SOURCE_DIR) / "CMakeLists.txt");
  std::smatch m;
  return std::regex_search(text, m, std::regex(R"(project\(tecido VERSION ([0-9.]+))")) ? m[1].str() : "";
}

/// `git rev-parse --short HEAD` of the source, or "unknown" when it is not a git checkout (or
/// there is no git), as the build decided at configure time.
std::string git_short_head() {
  const std::string cmd = "git -C '" + std::string(TECIDO_SOURCE_DIR) + "' rev-parse --short HEAD 2>/dev/null";
  std::string out;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[128];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    if (::pclose(p) != 0) out.clear();
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out.empty() || !std::filesystem::exists(std::filesystem::path(TECIDO_SOURCE_DIR) / ".git") ? "unknown" : out;
}

TEST(Provenance, VersionAndCommitAreTheBuildsOwn) {
  const std::string version = cmake_project_version();
  ASSERT_FALSE(version.empty());
  EXPECT_EQ(io::tecido_version(), version);
  EXPECT_EQ(io::tecido_commit(), git_short_head());
  EXPECT_EQ(io::version_line(), "tecido " + version + " (commit " + git_short_head() + ")");
}

TEST(Provenance, CommandLineIsQuotedForTheShell) {
  EXPECT_EQ(io::shell_line({"tecido", "suite", "order", "--quick", "--out", "/tmp/a-b_c.d/x:y,z=1+2@3%"}),
            "tecido suite order --quick --out /tmp/a-b_c.d/x:y,z=1+2@3%");
  EXPECT_EQ(io::shell_line({"tecido", "run", "my scene.json", "it's", ""}), "tecido run 'my scene.json' 'it'\\''s' ''");
  EXPECT_EQ(io::shell_line({"a$b", "*", "x\ny"}), "'a$b' '*' 'x\ny'");
}

TEST(Provenance, JsonAndMarkdownCarryAllThree) {
  const std::string before = io::command_line();
  const char* argv[] = {"tecido", "suite", "order", "--out", "my dir"};
  io::set_command_line(5, argv);
  EXPECT_EQ(io::command_line(), "tecido suite order --out 'my dir'");
  const io::Json j = io::provenance_json();
  EXPECT_EQ(j, (io::Json{{"version", io::tecido_version()}, {"commit", io::tecido_commit()},
                         {"command_line", "tecido suite order --out 'my dir'"}}));
  EXPECT_EQ(io::provenance_markdown(), std::string("tecido ") + io::tecido_version() + ", commit " + io::tecido_commit() +
                                           ": `tecido suite order --out 'my dir'`");
  // Put back what this process had (other tests compare outputs made in this process).
  io::set_command_line(0, nullptr);
  EXPECT_EQ(io::command_line(), "");
  EXPECT_EQ(before, "");
}

}  // namespace
}  // namespace tecido
