// Output directories (comparisons/io/output_dir.h): checked before the work starts, creating
// nothing; the message names the directory and what is in the way.
#include "tests/support/rejection.h"
#include "comparisons/io/output_dir.h"
#include "comparisons/io/output_error.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

std::string check(const std::string& dir) {
  try {
    io::check_output_dir(dir);
  } catch (const io::OutputError& e) {
    return e.what();
  }
  return "ok";
}

TEST(OutputDir, CheckCreatesNothingAndNamesTheObstacle) {
  const auto dir = testing::temp_dir("outdir");
  EXPECT_EQ(check((dir / "new" / "deeper").string()), "ok");
  EXPECT_FALSE(std::filesystem::exists(dir / "new"));
  EXPECT_EQ(check(dir.string()), "ok");
  testing::write_text(dir / "file", "x");
  EXPECT_EQ(check((dir / "file").string()),
            (dir / "file").string() + ": cannot write into this directory: " + (dir / "file").string() + " is not a directory");
  EXPECT_EQ(check((dir / "file" / "frames").string()),
            (dir / "file" / "frames").string() + ": cannot write into this directory: " + (dir / "file").string() +
                " is not a directory");
  EXPECT_EQ(check("/dev/null/x/frames"), "/dev/null/x/frames: cannot write into this directory: /dev/null is not a directory");
  std::filesystem::remove_all(dir);
}

TEST(OutputDir, CreateNamesTheObstacle) {
  const auto dir = testing::temp_dir("outdir-create");
  io::create_output_directories((dir / "a" / "b").string());
  EXPECT_TRUE(std::filesystem::is_directory(dir / "a" / "b"));
  testing::write_text(dir / "f", "x");
  try {
    io::create_output_directories((dir / "f" / "g").string());
    ADD_FAILURE() << "created";
  } catch (const io::OutputError& e) {
    EXPECT_EQ(e.path(), (dir / "f" / "g").string());
    EXPECT_EQ(e.problem(), "cannot create directory: " + (dir / "f").string() + " is not a directory");
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido
