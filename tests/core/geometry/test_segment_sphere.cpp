// Segment against a solid sphere: hand-worked entries, grazes, exits, tunnels, and the placement
// on the surface.
#include "core/geometry/segment_sphere.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido {
namespace {

TEST(SegmentSphere, StraightDropEntersHalfway) {
  // From 2 above the centre to the centre: |2 - 2s| = 1 at s = 1/2.
  const SphereEntry e = segment_enters_sphere(Vec3(0, 0, 2), Vec3(0, 0, 0), 1.0);
  ASSERT_TRUE(e.hit);
  EXPECT_DOUBLE_EQ(e.s, 0.5);
}

TEST(SegmentSphere, TunnelThroughIsSeenAtTheFirstRoot) {
  // (0, 0, 3) -> (0, 0, -3): |3 - 6s| = 1 at s = 1/3 and 2/3; both ends outside.
  const SphereEntry e = segment_enters_sphere(Vec3(0, 0, 3), Vec3(0, 0, -3), 1.0);
  ASSERT_TRUE(e.hit);
  EXPECT_NEAR(e.s, 1.0 / 3.0, 1e-15);
}

TEST(SegmentSphere, ObliqueEntryAtTheChordRoot) {
  // Along y = 0, z = 1/2 from x = -2 to x = 2: reaches x = -sqrt(3)/2 at s = (2 - sqrt(3)/2) / 4.
  const SphereEntry e = segment_enters_sphere(Vec3(-2, 0, 0.5), Vec3(2, 0, 0.5), 1.0);
  ASSERT_TRUE(e.hit);
  EXPECT_NEAR(e.s, (2.0 - std::sqrt(3.0) / 2.0) / 4.0, 1e-15);
}

TEST(SegmentSphere, GrazingTangentIsNoHit) {
  // The line y = 1 touches the unit sphere at (0, 1, 0) without entering the open ball.
  EXPECT_FALSE(segment_enters_sphere(Vec3(-2, 1, 0), Vec3(2, 1, 0), 1.0).hit);
  // A path that passes by.
  EXPECT_FALSE(segment_enters_sphere(Vec3(-2, 1.5, 0), Vec3(2, 1.5, 0), 1.0).hit);
}

TEST(SegmentSphere, LeavingFromTheSurfaceIsNoHitEnteringIsAtZero) {
  EXPECT_FALSE(segment_enters_sphere(Vec3(0, 0, 1), Vec3(0, 0, 2), 1.0).hit);
  EXPECT_FALSE(segment_enters_sphere(Vec3(0, 0, 1), Vec3(1, 0, 1), 1.0).hit);  // along the tangent plane
  const SphereEntry in = segment_enters_sphere(Vec3(0, 0, 1), Vec3(0, 0, 0.5), 1.0);
  ASSERT_TRUE(in.hit);
  EXPECT_EQ(in.s, 0.0);
}

TEST(SegmentSphere, EndingOnTheSurfaceIsNoHitEndingInsideAlwaysIs) {
  EXPECT_FALSE(segment_enters_sphere(Vec3(0, 0, 2), Vec3(0, 0, 1), 1.0).hit);
  // A zero-length path strictly inside (only an initial state can be there).
  EXPECT_TRUE(segment_enters_sphere(Vec3(0, 0, 0.5), Vec3(0, 0, 0.5), 1.0).hit);
}

TEST(SegmentSphere, PlacementIsOnTheSurfaceAndNeverInside) {
  for (const Vec3& r : {Vec3(0.3, -0.2, 0.1), Vec3(1e-3, 2.0, -7.0), Vec3(0, 0, 0)}) {
    for (double radius : {1e-6, 0.1, 1.0, 1e6}) {
      const Vec3 x = place_on_sphere(r, radius);
      EXPECT_FALSE(inside_sphere(x, radius));
      EXPECT_NEAR(x.norm(), radius, 8 * radius * 0x1p-52);
    }
  }
}

}  // namespace
}  // namespace tecido
