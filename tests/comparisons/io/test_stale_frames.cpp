// Frames of an earlier run (comparisons/io/stale_frames.h): tecido's own frame names are
// recognised and removed, every other file is left alone.
#include "tests/support/cli_runner.h"
#include "comparisons/io/stale_frames.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

namespace tecido {
namespace {

namespace fs = std::filesystem;

TEST(StaleFrames, FrameNamesAreFrameWritersOwn) {
  for (const char* name : {"frame_000000.obj", "frame_000120.vtk", "frame_1234567.obj"})
    EXPECT_TRUE(io::is_frame_file_name(name)) << name;
  for (const char* name : {"frame_12.obj", "frame_000012.obj.orig", "frame_000012.png", "frame_00001a.obj", "frame_.obj",
                           "myframe_000012.obj", "frame_000012", "result.json", ".frame_000012.obj.tmp.1"})
    EXPECT_FALSE(io::is_frame_file_name(name)) << name;
}

TEST(StaleFrames, OnlyRegularFramesAreRemoved) {
  const auto dir = testing::temp_dir("stale-frames");
  EXPECT_EQ(io::remove_stale_frames((dir / "missing").string()), 0u);
  for (const char* name : {"frame_000000.obj", "frame_000010.obj", "frame_000010.vtk", "frame_12.obj", "notes.txt"})
    testing::write_text(dir / name, "x");
  fs::create_directory(dir / "frame_000020.obj");  // a directory of that name is not a frame
  fs::create_symlink(dir / "notes.txt", dir / "frame_000030.obj");  // nor is a link
  EXPECT_EQ(io::remove_stale_frames(dir.string()), 3u);
  std::set<std::string> left;
  for (const auto& e : fs::directory_iterator(dir)) left.insert(e.path().filename().string());
  EXPECT_EQ(left, (std::set<std::string>{"frame_12.obj", "notes.txt", "frame_000020.obj", "frame_000030.obj"}));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tecido
