// Writing outputs (comparisons/io/atomic_file.h): every failure is an io::OutputError naming the
// path, and neither the target nor a temporary file is left half written.
#include "tests/support/rejection.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/io/output_error.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

std::string failure(const std::function<void()>& write) {
  try {
    write();
  } catch (const io::OutputError& e) {
    return e.what();
  }
  return "written";
}

// /dev/full accepts the open and fails every write with ENOSPC: a full disk.
TEST(AtomicFile, AFullDiskIsAnOutputErrorNamingThePath) {
  EXPECT_EQ(failure([] { io::write_whole_file("/dev/full", "some content\n"); }),
            "/dev/full: cannot write: No space left on device");
}

TEST(AtomicFile, WritesWholeFilesAndReplacesOldOnes) {
  const auto dir = testing::temp_dir("atomic");
  const auto target = (dir / "a" / "b" / "result.json").string();
  io::write_file_atomic(target, "first\n");
  io::write_file_atomic(target, "second\n");
  EXPECT_EQ(testing::slurp(target), "second\n");
  EXPECT_TRUE(testing::files_named(dir, ".tmp.").empty());
  std::filesystem::remove_all(dir);
}

TEST(AtomicFile, ANonDirectoryOnThePathIsAnOutputErrorAndNothingIsWritten) {
  const auto dir = testing::temp_dir("atomic-bad");
  testing::write_text(dir / "file", "x");
  EXPECT_EQ(failure([&] { io::write_file_atomic((dir / "file" / "sub" / "r.json").string(), "x"); }),
            (dir / "file" / "sub").string() + ": cannot create directory: " + (dir / "file").string() + " is not a directory");
  EXPECT_EQ(failure([] { io::write_file_atomic("/dev/null/x/r.json", "x"); }),
            "/dev/null/x: cannot create directory: /dev/null is not a directory");
  // A directory where the file should be: the temporary file is written, the rename fails, and
  // the temporary file is removed again.
  std::filesystem::create_directories(dir / "result.json");
  EXPECT_EQ(failure([&] { io::write_file_atomic((dir / "result.json").string(), "x"); }),
            (dir / "result.json").string() + ": cannot replace the file: Is a directory");
  EXPECT_TRUE(testing::files_named(dir, ".tmp.").empty());
  std::filesystem::remove_all(dir);
}

TEST(AtomicFile, AnUnwritableDirectoryIsAnOutputError) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only directories";
  const auto dir = testing::temp_dir("atomic-ro");
  std::filesystem::create_directories(dir / "ro");
  std::filesystem::permissions(dir / "ro", std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  EXPECT_EQ(failure([&] { io::write_file_atomic((dir / "ro" / "r.json").string(), "x"); }),
            (dir / "ro" / "r.json").string() + ": cannot create a file: Permission denied");
  std::filesystem::permissions(dir / "ro", std::filesystem::perms::owner_all);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
