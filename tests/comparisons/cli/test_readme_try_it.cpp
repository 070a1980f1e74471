// The README as a newcomer meets it: it stays a few screens long, its "Try it" and "Validate your
// own engine" commands run as written and write what it says they write, and every link of the
// README and docs/ reaches a page and a heading that exist.
#include "comparisons/io/source_dir.h"
#include "tests/support/cli_runner.h"
#include "tests/support/markdown_blocks.h"
#include "tests/support/markdown_links.h"
#include "tests/support/outside_fixtures.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <algorithm>

namespace tecido {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kSourceDir = TECIDO_SOURCE_DIR;

std::string readme_text() { return testing::slurp(kSourceDir / "README.md"); }

/// A directory laid out like the repository root as the README's commands expect it: the
/// sources a command reads (data/, examples/, include/) and the built CLI and example plug-in
/// at the paths the release preset gives them (build/bin/tecido, build/lib/...), whatever
/// preset built this test.
fs::path readme_sandbox(const std::string& name) {
  const fs::path dir = testing::temp_dir(name);
  for (const char* src : {"data", "examples", "include"}) fs::create_directory_symlink(kSourceDir / src, dir / src);
  fs::create_directories(dir / "build/bin");
  fs::create_directories(dir / "build/lib");
  fs::create_symlink(TECIDO_CLI, dir / "build/bin/tecido");
  fs::create_symlink(testing::kExamplePlugin, dir / "build/lib/libtecido_example_plugin.so");
  return dir;
}

/// One command run by /bin/sh in `dir`, as a reader would type it there.
testing::CliResult run_readme_command(const fs::path& dir, const std::string& command) {
  testing::write_text(dir / "command.sh", command + "\n");
  const std::string sh = "cd " + testing::quoted(dir.string()) + " && /bin/sh command.sh >command.out 2>command.err";
  const int status = std::system(sh.c_str());
  testing::CliResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = testing::slurp(dir / "command.out");
  r.err = testing::slurp(dir / "command.err");
  return r;
}

/// Runs every command of the README's block under `heading`, each expected to exit as its
/// comment promises (0 unless it says "exits N"), and returns what each printed, in order.
/// `cmake` lines are skipped: this test's own build has run them.
std::vector<testing::CliResult> run_readme_block(const fs::path& dir, const std::string& heading) {
  const std::vector<std::string> commands = testing::shell_commands(testing::sh_block_under(readme_text(), heading));
  EXPECT_FALSE(commands.empty()) << "README.md has no ```sh block under \"" << heading << "\"";
  std::vector<testing::CliResult> results;
  for (const std::string& command : commands) {
    if (command.rfind("cmake ", 0) == 0) continue;
    results.push_back(run_readme_command(dir, command));
    const testing::CliResult& r = results.back();
    EXPECT_EQ(r.code, testing::promised_exit(command)) << command << "\nstdout: " << r.out << "\nstderr: " << r.err;
  }
  return results;
}

/// The answer of `engine` to the pair `id` in `tecido tritri --json` output.
json readme_tritri_answer(const json& out, const std::string& id, const std::string& engine) {
  for (const json& r : out["results"])
    if (r["id"] == id) return r[engine];
  return nullptr;
}

/// The name of the first failed check of the report whose name contains `engine`, "" if none.
std::string readme_failed_check(const json& report, const std::string& engine) {
  std::string found;
  auto visit = [&](const json& v, const auto& self) -> void {
    if (!found.empty()) return;
    if (v.is_object() && v.contains("name") && v.contains("pass") && v["pass"] == false &&
        v["name"].get<std::string>().find(engine) != std::string::npos) {
      found = v["name"].get<std::string>();
      return;
    }
    if (v.is_structured())
      for (const json& child : v) self(child, self);
  };
  visit(report, visit);
  return found;
}

TEST(Readme, StaysAFewScreens) {
  const std::vector<std::string> lines = testing::text_lines(readme_text());
  EXPECT_LE(lines.size(), 150u) << "the README is the way in; reference material belongs in docs/";
  std::size_t longest = 0;
  for (const std::string& line : lines) longest = std::max(longest, line.size());
  EXPECT_LE(longest, 200u) << "a line (a table cell holding a paragraph?) too long to read rendered";
}

TEST(Readme, TryItRunsAsWrittenAndWritesWhatItSays) {
  const fs::path dir = readme_sandbox("readme-try-it");
  run_readme_block(dir, "Try it");
  // What the README says the run writes: the result, a frame per 15 steps of cloth_on_sphere.json's
  // 1500 (the first and the last named), and the key-frame picture when gnuplot is there.
  const std::string readme = readme_text();
  for (const char* named : {"out/try/result.json", "frame_000000.obj", "frame_001500.obj", "cloth.svg"})
    EXPECT_NE(readme.find(named), std::string::npos) << named;
  ASSERT_TRUE(fs::exists(dir / "out/try/result.json")) << "the Try it block wrote no out/try/result.json";
  const json result = json::parse(testing::slurp(dir / "out/try/result.json"));
  EXPECT_EQ(result["status"], "ok");
  EXPECT_EQ(result["steps"], 1500);
  EXPECT_TRUE(fs::exists(dir / "out/try/frames/frame_000000.obj"));
  EXPECT_TRUE(fs::exists(dir / "out/try/frames/frame_001500.obj"));
  if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
    EXPECT_TRUE(fs::exists(dir / "out/try/cloth.svg"));
  }
  fs::remove_all(dir);
}

TEST(Readme, ValidateYourEngineRunsAsWritten) {
  const fs::path dir = readme_sandbox("readme-engine");
  const std::vector<testing::CliResult> runs = run_readme_block(dir, "Validate your own engine in three commands");
  ASSERT_EQ(runs.size(), 3u) << "three commands: build the engine, ask it, run the suites";
  // What the README says of the second command: mt-plugin says false where exact says true.
  const json answers = json::parse(runs[1].out, nullptr, false);
  ASSERT_FALSE(answers.is_discarded()) << "the second command printed no JSON: " << runs[1].out;
  for (const char* id : {"stab", "coplanar", "touching"}) {
    EXPECT_EQ(readme_tritri_answer(answers, id, "mt-plugin"), false) << id;
    EXPECT_EQ(readme_tritri_answer(answers, id, "exact"), true) << id;
  }
  // And of the third: the report names the plug-in, and checks of both example engines failed.
  ASSERT_TRUE(fs::exists(dir / "out/mine/report.json")) << "the third command wrote no out/mine/report.json";
  const json report = json::parse(testing::slurp(dir / "out/mine/report.json"));
  EXPECT_NE(report["outside_engines"].dump().find("libmy_engine.so"), std::string::npos) << report["outside_engines"];
  for (const char* engine : {"mt-plugin", "sampled-ccd"})
    EXPECT_NE(readme_failed_check(report, engine), "") << engine << " failed no check";
  EXPECT_TRUE(fs::exists(dir / "out/mine/report.md"));
  EXPECT_TRUE(fs::exists(dir / "out/mine/ccd/disagreements.json"));
  fs::remove_all(dir);
}

TEST(Readme, LinksReachPagesAndHeadingsThatExist) {
  std::vector<fs::path> pages = {kSourceDir / "README.md"};
  for (const auto& entry : fs::directory_iterator(kSourceDir / "docs"))
    if (entry.path().extension() == ".md") pages.push_back(entry.path());
  for (const fs::path& page : pages)
    for (const std::string& link : testing::relative_links(testing::slurp(page))) {
      const std::size_t hash = link.find('#');
      const fs::path target = hash == 0 ? page : page.parent_path() / link.substr(0, hash);
      ASSERT_TRUE(fs::exists(target)) << page.filename() << ": " << link;
      if (hash == std::string::npos || fs::is_directory(target)) continue;
      const std::set<std::string> anchors = testing::page_anchors(testing::slurp(target));
      EXPECT_TRUE(anchors.count(link.substr(hash + 1))) << page.filename() << ": " << link;
    }
}

}  // namespace
}  // namespace tecido
