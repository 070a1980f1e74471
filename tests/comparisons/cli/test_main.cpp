// How the command line reports what it cannot do (comparisons/cli/main.cpp): every output that
// cannot be created or written, stdout included, exits 2 with one line naming the path, before
// the work when it can be known then, with no half-written file; hostile text in a message stays
// on one line.
#include "tests/support/rejection.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

using testing::expect_rejected;
using testing::run_cli;

const char* kScene = R"({"dt":0.01,"steps":20,"particles":[{"position":[0,0,1],"mass":1}]})";

class OutputErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::temp_dir("output-errors");
    testing::write_text(dir_ / "s.json", kScene);
    testing::write_text(dir_ / "file", "not a directory");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string scene() const { return "'" + (dir_ / "s.json").string() + "'"; }
  std::filesystem::path dir_;
};

// The issue's case: exit 3 and "filesystem error" before.
TEST_F(OutputErrors, AnOutDirUnderAFileIsExitTwoNamingThePathForEveryCommand) {
  expect_rejected(run_cli("run " + scene() + " --out /dev/null/x"),
                  {"tecido: /dev/null/x/frames: cannot write into this directory: /dev/null is not a directory"}, "run");
  const std::string f = (dir_ / "file").string();
  for (const std::string& c : {"run " + scene() + " --out '" + f + "'", "suite order --out '" + f + "'",
                               "experiment self-contact --quick --runs 0 --out '" + f + "'",
                               "suite tritri --quick --shard 0/4 --out '" + f + "/sub'"}) {
    expect_rejected(run_cli(c), {f, ": cannot write into this directory: " + f + " is not a directory"}, c);
  }
  EXPECT_EQ(testing::slurp(dir_ / "file"), "not a directory");
}

TEST_F(OutputErrors, MergeChecksItsOutDirBeforeWriting) {
  const std::string shard = (dir_ / "shard").string();
  ASSERT_EQ(run_cli("experiment self-contact --quick --runs 0 --shard 0/1 --out '" + shard + "'").code, 0);
  expect_rejected(run_cli("merge '" + shard + "' --out /dev/null/merged"),
                  {"/dev/null/merged: cannot write into this directory: /dev/null is not a directory"}, "merge");
}

// A full disk, as far as it can be simulated for a whole command: a file-size limit (ulimit -f 4,
// a few KB: room for the message on stderr, not for a frame of 2000 particles) makes a write fail
// part-way (EFBIG); the run stops there, names the file, and leaves no temporary file and no
// result.json.
TEST_F(OutputErrors, AFailedWriteMidRunIsExitTwoWithNothingHalfWritten) {
  std::string big = R"({"dt":0.01,"steps":20,"particles":[)";
  for (int k = 0; k < 2000; ++k) big += std::string(k ? "," : "") + "{\"position\":[" + std::to_string(k) + ".125,0.5,1.75],\"mass\":1}";
  testing::write_text(dir_ / "big.json", big + "]}");
  const auto out = dir_ / "out";
  const auto r = testing::run_cli_with("ulimit -f 4", "run '" + (dir_ / "big.json").string() + "' --out '" + out.string() + "'");
  expect_rejected(r, {(out / "frames" / "frame_000000.obj").string() + ": cannot write: File too large"}, "run, ulimit -f 4");
  EXPECT_FALSE(std::filesystem::exists(out / "result.json"));
  EXPECT_TRUE(testing::files_named(out, ".tmp.").empty());
  // A suite: its progress goes to stderr too; the error is a line of its own, naming the file.
  const auto s = testing::run_cli_with("ulimit -f 4", "suite order --out '" + out.string() + "'");
  EXPECT_EQ(s.code, 2) << s.err;
  EXPECT_NE(s.err.find("\ntecido: " + out.string() + "/"), std::string::npos) << s.err;
  EXPECT_NE(s.err.find(": cannot write: File too large\n"), std::string::npos) << s.err;
  EXPECT_FALSE(std::filesystem::exists(out / "report.json"));
  EXPECT_TRUE(testing::files_named(out, ".tmp.").empty());
}

TEST_F(OutputErrors, StdoutThatCannotBeWrittenIsExitTwo) {
  const auto r = testing::run_cli_with("true", "run " + scene() + " --json", "/dev/full");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err, "tecido: stdout: cannot write: No space left on device\n");
  const auto help = testing::run_cli_with("true", "run --help", "/dev/full");
  EXPECT_EQ(help.code, 2) << help.err;
}

// A key with a newline, an escape and a bell in it is quoted in the message: still one line.
TEST_F(OutputErrors, HostileTextInAMessageStaysOnOneLine) {
  testing::write_text(dir_ / "k.json", "{\"dt\":0.01,\"steps\":1,\"a\\nb\\u001b[2J\\u0007\":1}");
  expect_rejected(run_cli("run '" + (dir_ / "k.json").string() + "'"), {"/a\\nb\\x1b[2J\\x07: unknown key"}, "control characters");
  std::string key(100000, 'k');
  testing::write_text(dir_ / "long.json", "{\"dt\":0.01,\"steps\":1,\"" + key + "\":1}");
  const auto r = run_cli("run '" + (dir_ / "long.json").string() + "'");
  expect_rejected(r, {" ... ", "(allowed: integrator, dt, steps, ", "); keys starting with '_' are comments"}, "long key");
  EXPECT_LT(r.err.size(), 2100u);
}

}  // namespace
}  // namespace tecido
