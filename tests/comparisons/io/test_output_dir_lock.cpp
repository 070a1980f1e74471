// One run at a time per output directory (comparisons/io/output_dir.h, OutputDirLock): a second
// claim on a directory, from another process (fork) or from another `tecido` process, refuses
// with one line naming the holder's pid (known here independently: the holder is this test
// process), and nothing of the refused run is written; a claim on a directory that does not
// exist yet is taken when it is created, and a released claim can be taken again.
#include "comparisons/io/source_dir.h"
#include "tests/support/cli_runner.h"
#include "tests/support/rejection.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/io/output_dir.h"
#include "comparisons/io/output_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sys/wait.h>
#include <unistd.h>

namespace tecido {
namespace {

std::string refusal(const std::string& dir, pid_t holder) {
  return dir + ": another tecido run (pid " + std::to_string(holder) +
         ") is writing into this directory; wait for it to end or choose another --out";
}

std::string claim(const std::string& dir) {
  try {
    io::OutputDirLock lock(dir);
    return lock.held() ? "held" : "pending";
  } catch (const io::OutputError& e) {
    return e.what();
  }
}

TEST(OutputDirLock, AnotherProcessIsRefusedWithTheHoldersPid) {
  const auto dir = testing::temp_dir("outlock-fork").string();
  io::create_output_directories(dir);
  {
    const io::OutputDirLock held(dir);
    ASSERT_TRUE(held.held());
    const pid_t parent = ::getpid();
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) _exit(claim(dir) == refusal(dir, parent) ? 0 : 1);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "the child was not refused with " << refusal(dir, parent);
    // Within one process too (each claim is its own open file description).
    EXPECT_EQ(claim(dir), refusal(dir, parent));
  }
  EXPECT_EQ(claim(dir), "held");  // released with its owner
  std::filesystem::remove_all(dir);
}

TEST(OutputDirLock, AMissingDirectoryIsClaimedWhenCreatedAndNothingIsCreatedBefore) {
  const auto base = testing::temp_dir("outlock-new");
  const std::string dir = (base / "out").string();
  const io::OutputDirLock lock(dir);
  EXPECT_FALSE(lock.held());
  EXPECT_FALSE(std::filesystem::exists(dir));
  io::write_file_atomic(dir + "/frames/f.txt", "x");  // creates out/frames: out is claimed
  EXPECT_TRUE(lock.held());
  EXPECT_EQ(claim(dir), refusal(dir, ::getpid()));
  std::filesystem::remove_all(base);
}

TEST(OutputDirLock, ASecondTecidoRunIntoTheSameOutRefusesWithOneLineAndExitCode2) {
  const auto dir = testing::temp_dir("outlock-cli");
  const std::string out = (dir / "out").string();
  io::create_output_directories(out);
  const io::OutputDirLock held(out);  // this test process plays the first run
  const std::string scene = std::string(TECIDO_SOURCE_DIR) + "/data/scenes/cloth_on_sphere.json";
  for (const std::string& args : {"run '" + scene + "' --steps 2 --out '" + out + "'", "suite stability --quick --out '" + out + "'"}) {
    const auto r = testing::run_cli(args);
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(r.err, "tecido: " + refusal(out, ::getpid()) + "\n") << args;
  }
  EXPECT_TRUE(std::filesystem::is_empty(out));  // the refused runs wrote nothing
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
