// The forced-contact scene (comparisons/suites/forced_contact/scene.h, run.h): the fold keeps every
// distance along the cloth, the timeline is the stated one, the grips really force the layers
// through each other during the hold (the exact test counts pairs) whatever the response, and with
// no response nothing holds the crossing once the grips let go (each layer falls back to hanging
// on its own side), so the cloth ends free.
#include "comparisons/suites/forced_contact/run.h"
#include "core/scene/cloth_builder.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido {
namespace {

namespace fc = suites::forced_contact;

TEST(ForcedContactScene, TheFoldKeepsDistancesAlongTheCloth) {
  fc::ForcedScene f;
  f.offset = 0.0;
  const Scene s = fc::forced_scene(f, SelfCollisionResponse::None, 0.5, 1.0, 0);
  const auto x = [&](int r, int c) { return s.particles.x[cloth_node(*s.cloth, s.cloth_first_particle, r, c)]; };
  for (int r = 0; r < f.rows; ++r)
    for (int c = 0; c + 1 < f.cols; ++c) EXPECT_NEAR((x(r, c + 1) - x(r, c)).norm(), f.spacing, 1e-12);
  // Down the length: the straight parts exactly, the arc's chords a little shorter (2 r sin(s / 2r)).
  const double chord = 2 * f.bar_radius * std::sin(f.spacing / (2 * f.bar_radius));
  for (int r = 0; r + 1 < f.rows; ++r) {
    const double d = (x(r + 1, 3) - x(r, 3)).norm();
    EXPECT_LE(d, f.spacing + 1e-12);
    EXPECT_GE(d, chord - 1e-12);
  }
  // The layers hang 2r apart, the front one at -z; the bar rows are fixed.
  EXPECT_NEAR(x(0, 0).z(), -f.bar_radius, 1e-12);
  EXPECT_NEAR(x(f.rows - 1, 0).z(), f.bar_radius, 1e-12);
  for (int r : f.bar_rows) EXPECT_EQ(s.particles.pinned[cloth_node(*s.cloth, s.cloth_first_particle, r, 0)], 1);
  EXPECT_EQ(s.self_collision->detection, SelfCollisionDetection::Discrete);
  EXPECT_EQ(fc::forced_scene(f, SelfCollisionResponse::Impulse, 0.5, 1.0, 0).self_collision->detection,
            SelfCollisionDetection::Continuous);
}

TEST(ForcedContactScene, TimelineIsTheStatedOne) {
  const fc::ForcedScene f;  // settle 1.5 s, 0.4 m at 0.5 m/s, dt 0.01
  const fc::Timeline t = fc::timeline(f, 0.6, 4.0);
  EXPECT_EQ(t.grip, 150);
  EXPECT_EQ(t.moved, 230);
  EXPECT_EQ(t.release, 290);
  EXPECT_EQ(t.end, 690);
  EXPECT_EQ(fc::timeline(f, 0.0, 4.0).release, 231);  // at least one held step
  const auto g = fc::grips(f);
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[0].particles.size(), 4u);
  EXPECT_EQ(g[0].particles.front(), 3 * f.cols + 4);
  EXPECT_EQ(g[1].direction, -1.0);
}

TEST(ForcedContactScene, RunsDifferOnlyByTheirOffsets) {
  const fc::ForcedScene f;
  const Scene a = fc::forced_scene(f, SelfCollisionResponse::None, 0.5, 1.0, 0);
  const Scene b = fc::forced_scene(f, SelfCollisionResponse::Gia, 0.5, 1.0, 0);
  const Scene c = fc::forced_scene(f, SelfCollisionResponse::None, 0.5, 1.0, 1);
  EXPECT_EQ(a.particles.x, b.particles.x);  // the same run index starts alike whatever the response
  EXPECT_NE(a.particles.x, c.particles.x);
  for (std::size_t i = 0; i < a.particles.size(); ++i)
    EXPECT_LE((a.particles.x[i] - c.particles.x[i]).lpNorm<Eigen::Infinity>(), 2 * f.offset + 1e-12);
}

class ForcedContactHold : public ::testing::TestWithParam<SelfCollisionResponse> {};

TEST_P(ForcedContactHold, TheGripsForceAnIntersectionDuringTheHold) {
  const fc::Settings s = fc::settings(true);
  const fc::RunResult r = fc::run_forced(fc::ForcedScene{}, s, GetParam(), s.holds.back(), 0);
  ASSERT_EQ(r.status, "ok");
  EXPECT_GT(r.held_pairs, 0) << self_collision_response_name(GetParam());
  EXPECT_GT(r.hold_max_pairs, 0);
  // Before the grips take hold the cloth hangs free: the series starts at zero.
  ASSERT_FALSE(r.series.empty());
  EXPECT_EQ(r.series.front(), 0);
}

INSTANTIATE_TEST_SUITE_P(Responses, ForcedContactHold,
                         ::testing::Values(SelfCollisionResponse::None, SelfCollisionResponse::Gia,
                                           SelfCollisionResponse::Impulse));

TEST(ForcedContactScene, WithNoResponseNothingHoldsTheCrossing) {
  // No response: the layers do not act on each other, each falls back to hanging on its own side
  // (z = -r and +r, planes that do not meet), so the run ends free within the stated horizon.
  const fc::Settings s = fc::settings(false);
  const fc::RunResult r = fc::run_forced(fc::ForcedScene{}, s, SelfCollisionResponse::None, s.holds.front(), 0);
  ASSERT_EQ(r.status, "ok");
  EXPECT_GT(r.held_pairs, 0);
  EXPECT_TRUE(r.free_at_end);
  EXPECT_TRUE(r.recovered);
}

}  // namespace
}  // namespace tecido
