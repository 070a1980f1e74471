// Hostile JSON-lines engines through the command line, as a user meets them: an engine that floods
// one reply without a newline, one that trickles a reply forever, one that answers with terminal
// escape sequences and bytes that are not text, and one of a protocol tecido does not speak. Each
// ends in exit 2 with one line naming the engine and what it did, in bounded time, and nothing the
// engine wrote reaches the terminal as anything but text.
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

namespace tecido {
namespace {

using testing::quoted;
using testing::run_cli;

/// One pair of triangles: enough for `tecido tritri` to say hello and ask one question.
std::string one_pair_file(const std::filesystem::path& dir) {
  const std::string path = (dir / "pair.json").string();
  testing::write_text(path, R"({"pairs":[{"id":"p","a":[[0,0,0],[1,0,0],[0,1,0]],"b":[[0,0,1],[1,0,1],[0,1,1]]}]})");
  return path;
}

/// `tecido tritri` on one pair with the process engine `hostile`, the shell script `script` (which
/// reads the hello request first), and the wall time it took.
testing::CliResult tritri_with(const std::string& script, const std::string& extra, double* seconds) {
  const auto dir = testing::temp_dir("hostile-engine");
  testing::write_text(dir / "engine.sh", script + "\n");
  const auto t0 = std::chrono::steady_clock::now();
  auto r = run_cli("tritri --pairs " + quoted(one_pair_file(dir)) + " --engine-cmd " +
                   quoted("hostile=sh " + (dir / "engine.sh").string()) + " --engines hostile " + extra + " --json");
  *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::filesystem::remove_all(dir);
  return r;
}

TEST(CliHostileEngines, AReplyThatNeverEndsIsStoppedAtTheTimeout) {
  double s = 0;
  const auto r = tritri_with(R"(read -r l; echo '{"protocol":1,"supports":["tri_tri"]}'; read -r l)"
                             "\nwhile :; do printf x; sleep 0.01; done",
                             "--engine-timeout 1", &s);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("engine hostile"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no whole reply within"), std::string::npos) << r.err;
  EXPECT_LT(s, 10.0);
}

TEST(CliHostileEngines, GarbageRepliesReachTheTerminalAsText) {
  double s = 0;
  const auto r = tritri_with("read -r l; printf '\\033]0;owned\\007\\033[2J\\377\\376{\\n'", "", &s);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("engine hostile"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\\x1b]0;owned\\x07\\x1b[2J\\xff\\xfe{"), std::string::npos) << r.err;
  for (const char c : r.err)  // one line of text: no control byte but its final newline, no byte of malformed UTF-8
    EXPECT_TRUE(c == '\n' || (static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f)) << r.err;
}

TEST(CliHostileEngines, AnotherProtocolIsOneClearLine) {
  double s = 0;
  const auto r = tritri_with(R"(read -r l; echo '{"protocol":2,"supports":["tri_tri"]}'; sleep 30)", "", &s);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("the engine speaks protocol 2, tecido speaks protocol 1"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

}  // namespace
}  // namespace tecido
