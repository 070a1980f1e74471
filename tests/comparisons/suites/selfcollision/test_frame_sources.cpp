// The selfcollision suite's frames (comparisons/suites/selfcollision/frame_recorder.* and
// frame_sources.*): a recording keeps at most the planned number of frames with and without a
// contact, judged by brute force over every pair (not the box tree the recorder uses), at the
// planned steps; the sources build the meshes they describe.
#include "comparisons/io/source_dir.h"
#include "comparisons/suites/selfcollision/frame_sources.h"

#include "core/cloth/self_collision.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace tecido::suites::selfcollision {
namespace {

const std::string kData = std::string(TECIDO_SOURCE_DIR) + "/data";

TEST(SelfcollisionFrames, SourcesHaveDistinctNames) {
  std::set<std::string> names;
  for (const FrameSource& s : frame_sources()) {
    EXPECT_TRUE(names.insert(s.name).second) << s.name;
    EXPECT_NE(s.record, nullptr);
    EXPECT_FALSE(s.about.empty());
  }
  EXPECT_EQ(names, (std::set<std::string>{"seed-fig21", "crumple"}));
}

/// Frames with and without a contact by brute force, and that the frames fall on the planned steps.
void expect_planned(const FrameSet& set, const Settings& s, double frame_dt) {
  ASSERT_FALSE(set.frames.empty());
  ASSERT_LE(set.frames.size(), static_cast<std::size_t>(s.frames_per_source));
  const long want_with = std::lround(s.frames_per_source * s.contact_share);
  long with = 0, without = 0;
  double last = 0.0;
  for (const Frame& f : set.frames) {
    (self_collision_pairs_brute(f.x, set.triangles).empty() ? without : with)++;
    const double steps = f.time / frame_dt;
    EXPECT_NEAR(steps, std::round(steps), 1e-6) << "a frame every " << frame_dt << " s, got t = " << f.time;
    EXPECT_GT(f.time, last);
    last = f.time;
  }
  EXPECT_LE(with, want_with);
  EXPECT_LE(without, s.frames_per_source - want_with);
  EXPECT_GT(with, 0) << "the source is meant to touch itself";
}

TEST(SelfcollisionFrames, CrumpleKeepsThePlannedFrames) {
  Settings s = settings(true);
  const FrameSet set = crumple_frames(s, kData);
  EXPECT_EQ(set.triangles.size(), static_cast<std::size_t>(2 * (s.crumple_grid - 1) * (s.crumple_grid - 1)));
  expect_planned(set, s, s.crumple_every * 0.002);
}

TEST(SelfcollisionFrames, SeedSceneKeepsThePlannedFrames) {
  Settings s = settings(true);
  const FrameSet set = seed_fig21_frames(s, kData);
  EXPECT_EQ(set.triangles.size(), 2u * 15u * 15u) << "the seed scene's 16 x 16 cloth";
  expect_planned(set, s, s.seed_frame_interval);
}

}  // namespace
}  // namespace tecido::suites::selfcollision
