// Reading an input file (comparisons/io/text_file.h): at most io::kMaxInputBytes, so that neither
// a huge file nor a stream without end is read whole.
#include "tests/support/rejection.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"
#include "comparisons/io/text_file.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

namespace tecido {
namespace {

/// A sparse file of `size` bytes (no disk blocks are written).
void make_sparse(const std::filesystem::path& p, std::size_t size) {
  std::filesystem::remove(p);
  const int fd = ::open(p.c_str(), O_WRONLY | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::ftruncate(fd, static_cast<off_t>(size)), 0);
  ::close(fd);
}

TEST(TextFile, AFileAtTheLimitIsReadOneByteMoreIsRejectedByItsSize) {
  const auto dir = testing::temp_dir("size-limit");
  make_sparse(dir / "at.json", io::kMaxInputBytes);
  EXPECT_EQ(io::read_text_file((dir / "at.json").string()).size(), io::kMaxInputBytes);
  make_sparse(dir / "over.json", io::kMaxInputBytes + 1);
  try {
    io::read_text_file((dir / "over.json").string());
    ADD_FAILURE() << "accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.problem(), "larger than the limit of 67108864 bytes (64 MiB) for an input file");
  }
  // Through the CLI, for the JSON readers and the OBJ reader alike.
  for (const std::string& args : {"run '" + (dir / "over.json").string() + "' --json",
                                  "selfcollide --mesh '" + (dir / "over.json").string() + "' --json"}) {
    testing::expect_rejected(testing::run_cli(args), {(dir / "over.json").string() + ": /: larger than the limit of 67108864 bytes"},
                             args);
  }
  std::filesystem::remove_all(dir);
}

// /dev/zero has no size and no end: rejected after one byte past the limit.
TEST(TextFile, AStreamWithoutEndIsRejectedAtTheLimit) {
  try {
    io::read_text_file("/dev/zero");
    ADD_FAILURE() << "accepted";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.file(), "/dev/zero");
    EXPECT_NE(e.problem().find("larger than the limit"), std::string::npos) << e.problem();
  }
  testing::expect_rejected(testing::run_cli("tritri --pairs /dev/zero --json"), {"/dev/zero: /: larger than the limit"},
                           "tritri /dev/zero");
}

}  // namespace
}  // namespace tecido
