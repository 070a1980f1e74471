// The process door's transport: lines in and out of a shell command; a child that dies, hangs,
// answers two lines or closes its output mid-line fails the round trip with what happened and the
// tail of its stderr, and every later round trip fails the same way.
#include "comparisons/engines/outside/json_lines_process.h"

#include <gtest/gtest.h>

#include <chrono>

namespace tecido::outside {
namespace {

using namespace std::chrono_literals;

std::string failure(JsonLinesProcess& p, const std::string& request, std::string* tail = nullptr) {
  try {
    p.round_trip(request);
  } catch (const ProcessFailure& f) {
    if (tail) *tail = f.stderr_tail();
    return f.what();
  }
  return "";
}

TEST(JsonLinesProcess, EchoesLinesInOrder) {
  JsonLinesProcess p("while read -r l; do echo \"got $l\"; done", 5s);
  EXPECT_EQ(p.round_trip("one"), "got one");
  EXPECT_EQ(p.round_trip("two"), "got two");
  EXPECT_EQ(p.round_trips(), 2);
}

TEST(JsonLinesProcess, LongLinesBothWays) {
  // 3 MB each way: more than any pipe buffer, so writing and reading must interleave with the child.
  JsonLinesProcess p("while read -r l; do echo \"$l$l\"; done", 20s);
  const std::string line(1500000, 'x');
  EXPECT_EQ(p.round_trip(line).size(), 2 * line.size());
}

TEST(JsonLinesProcess, DeathReportsStatusAndStderrTail) {
  JsonLinesProcess p("read -r l; echo 'first line' >&2; echo 'Traceback: boom' >&2; exit 3", 5s);
  std::string tail;
  const std::string what = failure(p, "x", &tail);
  EXPECT_NE(what.find("closed its output without a reply: exited with status 3"), std::string::npos) << what;
  EXPECT_EQ(tail, "first line | Traceback: boom");
  EXPECT_EQ(failure(p, "again"), what);  // later round trips fail the same way
}

TEST(JsonLinesProcess, KilledBySignal) {
  JsonLinesProcess p("read -r l; kill -9 $$", 5s);
  const std::string what = failure(p, "x");
  EXPECT_NE(what.find("killed by signal 9"), std::string::npos) << what;
}

TEST(JsonLinesProcess, HangPastTheTimeout) {
  JsonLinesProcess p("read -r l; echo ready; read -r l; echo 'thinking' >&2; sleep 30", 300ms);
  EXPECT_EQ(p.round_trip("hello"), "ready");
  const auto t0 = std::chrono::steady_clock::now();
  std::string tail;
  const std::string what = failure(p, "x", &tail);
  EXPECT_NE(what.find("no reply within 0.3 s (--engine-timeout)"), std::string::npos) << what;
  EXPECT_EQ(tail, "thinking");
  // The child's group was killed: the round trip did not wait for sleep 30.
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 10s);
}

TEST(JsonLinesProcess, FirstReplyHasTheStartUpAllowance) {
  // A slow start (an interpreter loading on a busy machine) is not a hang: the first reply may take
  // up to kStartupAllowance even when the timeout is shorter; the second may not.
  JsonLinesProcess p("sleep 1; read -r l; echo ready; read -r l; sleep 1; echo late", 300ms);
  EXPECT_EQ(p.round_trip("hello"), "ready");
  EXPECT_NE(failure(p, "x").find("no reply within 0.3 s"), std::string::npos);
}

TEST(JsonLinesProcess, ChildThatNeverReadsItsInput) {
  // 8 MB request to a child that stops reading: the write cannot finish, the deadline ends it.
  JsonLinesProcess p("read -r l; echo ready; sleep 30", 300ms);
  EXPECT_EQ(p.round_trip("hello"), "ready");
  const std::string what = failure(p, std::string(8 << 20, 'x'));
  EXPECT_NE(what.find("did not read its request within 0.3 s"), std::string::npos) << what;
}

TEST(JsonLinesProcess, TwoLinesForOneRequest) {
  JsonLinesProcess p("while read -r l; do printf 'a\\nb\\n'; done", 5s);
  EXPECT_EQ(p.round_trip("x"), "a");
  const std::string what = failure(p, "y");
  EXPECT_NE(what.find("more than one line"), std::string::npos) << what;
}

TEST(JsonLinesProcess, ClosedOutputMidLine) {
  JsonLinesProcess p("read -r l; printf 'half a line'; exit 0", 5s);
  const std::string what = failure(p, "x");
  EXPECT_NE(what.find("closed its output mid-line without a reply: exited with status 0"), std::string::npos) << what;
}

TEST(JsonLinesProcess, TheTimeoutBoundsTheWholeReplyNotTheSilence) {
  // A byte every 10 ms and never a newline: never silent for long, so only a deadline on the whole
  // reply stops it.
  JsonLinesProcess p("read -r l; echo ready; read -r l; while :; do printf x; sleep 0.01; done", 500ms);
  EXPECT_EQ(p.round_trip("hello"), "ready");
  const auto t0 = std::chrono::steady_clock::now();
  const std::string what = failure(p, "x");
  EXPECT_NE(what.find("no whole reply within "), std::string::npos) << what;
  EXPECT_NE(what.find("bytes without a newline by then"), std::string::npos) << what;
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 5s);
}

TEST(JsonLinesProcess, AReplyPastTheSizeLimitFailsThere) {
  // 4 MiB of zeros without a newline against a limit of 1 MiB: stopped at the limit, well before
  // the timeout.
  JsonLinesProcess p("read -r l; head -c 4194304 /dev/zero; sleep 30", 20s, std::size_t{1} << 20);
  const auto t0 = std::chrono::steady_clock::now();
  const std::string what = failure(p, "x");
  EXPECT_NE(what.find("a reply longer than the limit of 1 MiB (kMaxReplyBytes)"), std::string::npos) << what;
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 10s);
}

TEST(JsonLinesProcess, StderrBytesAreShownAsText) {
  // An escape sequence, a bell and a byte that is not UTF-8 reach messages as escapes; UTF-8 text stays.
  JsonLinesProcess p("read -r l; printf '\\033]0;owned\\007 \\377 a\\303\\247\\303\\243o\\r\\n' >&2; exit 3", 5s);
  std::string tail;
  failure(p, "x", &tail);
  EXPECT_EQ(tail, "\\x1b]0;owned\\x07 \\xff a\xc3\xa7\xc3\xa3o") << tail;
}

TEST(JsonLinesProcess, CommandNotFound) {
  JsonLinesProcess p("/nonexistent/engine --serve", 5s);
  std::string tail;
  const std::string what = failure(p, "x", &tail);
  EXPECT_NE(what.find("exited with status 127"), std::string::npos) << what;  // the shell's "not found"
  EXPECT_NE(tail.find("/nonexistent/engine"), std::string::npos) << tail;
}

}  // namespace
}  // namespace tecido::outside
