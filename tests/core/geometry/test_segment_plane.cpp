// Segment vs bounded plane (DETECTACOLISÃO with the seed's slips fixed): hand-worked cases.
#include "core/geometry/segment_plane.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

// Unit floor: z = 0, |x| <= 1, |y| <= 0.5 (forward = x, right = z x x = y).
BoundedPlane floor_plane() { return make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(1.0, 0.5), 0.0); }

TEST(SegmentPlane, RightIsNormalCrossForward) {
  EXPECT_EQ(floor_plane().right(), Vec3::UnitY());
}

TEST(SegmentPlane, CrossingInsideAtTheRightFraction) {
  const auto h = segment_plane(floor_plane(), Vec3(0.2, 0.1, 1.0), Vec3(0.2, 0.1, -3.0));
  ASSERT_TRUE(h.hit);
  EXPECT_DOUBLE_EQ(h.t, 0.25);
}

TEST(SegmentPlane, BothFromBelowToo) {  // two-sided
  const auto h = segment_plane(floor_plane(), Vec3(0, 0, -1.0), Vec3(0, 0, 1.0));
  ASSERT_TRUE(h.hit);
  EXPECT_DOUBLE_EQ(h.t, 0.5);
}

TEST(SegmentPlane, SameSideNeverHits) {  // the seed's SIGNAL(p1) = SIGNAL(p2) slip, fixed
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(0, 0, 1), Vec3(0, 0, 0.5)).hit);
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(0, 0, -1), Vec3(0.1, 0, -0.5)).hit);
}

TEST(SegmentPlane, CrossingOutsideTheRectangleMisses) {
  // Through the plane at x = 1.5 (beyond +hx) and at x = -1.5 (the missing lower bound of the seed).
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(1.5, 0, 1), Vec3(1.5, 0, -1)).hit);
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(-1.5, 0, 1), Vec3(-1.5, 0, -1)).hit);
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(0, -0.75, 1), Vec3(0, -0.75, -1)).hit);
}

TEST(SegmentPlane, CrossingTheBorderDiagonally) {
  // From inside-above to outside-below: crosses z=0 at x = 1.25 -> miss; at x = 0.75 -> hit.
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(0.5, 0, 1), Vec3(2.0, 0, -1)).hit);
  const auto h = segment_plane(floor_plane(), Vec3(0.5, 0, 1), Vec3(1.0, 0, -1));
  ASSERT_TRUE(h.hit);
  EXPECT_DOUBLE_EQ(h.t, 0.5);
}

TEST(SegmentPlane, ExactlyOnTheBorderAndCornerCount) {  // closed rectangle
  EXPECT_TRUE(segment_plane(floor_plane(), Vec3(1.0, 0, 1), Vec3(1.0, 0, -1)).hit);
  EXPECT_TRUE(segment_plane(floor_plane(), Vec3(1.0, 0.5, 1), Vec3(1.0, 0.5, -1)).hit);     // corner
  EXPECT_TRUE(segment_plane(floor_plane(), Vec3(-1.0, -0.5, 1), Vec3(-1.0, -0.5, -1)).hit); // opposite corner
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(1.0, 0.5000001, 1), Vec3(1.0, 0.5000001, -1)).hit);
}

TEST(SegmentPlane, StartingOnThePlane) {
  const auto h = segment_plane(floor_plane(), Vec3(0.3, 0.3, 0.0), Vec3(0.3, 0.3, -1.0));
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.t, 0.0);
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(3, 0, 0.0), Vec3(3, 0, -1.0)).hit);  // on the plane, outside
}

TEST(SegmentPlane, EndingOnThePlane) {
  const auto h = segment_plane(floor_plane(), Vec3(0.3, 0.3, 2.0), Vec3(0.3, 0.3, 0.0));
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.t, 1.0);
}

TEST(SegmentPlane, ParallelAboveMisses) {
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(-2, 0, 0.1), Vec3(2, 0, 0.1)).hit);
}

TEST(SegmentPlane, LyingInThePlaneHitsAtTheFirstPointInside) {
  // From x = -3 to x = 1 along y = 0 in the plane: enters the rectangle at x = -1, t = 0.5.
  const auto h = segment_plane(floor_plane(), Vec3(-3, 0, 0), Vec3(1, 0, 0));
  ASSERT_TRUE(h.hit);
  EXPECT_DOUBLE_EQ(h.t, 0.5);
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(-3, 0.6, 0), Vec3(1, 0.6, 0)).hit);
  const auto inside = segment_plane(floor_plane(), Vec3(0, 0, 0), Vec3(0.5, 0, 0));
  ASSERT_TRUE(inside.hit);
  EXPECT_EQ(inside.t, 0.0);
}

TEST(SegmentPlane, GrazingTheEdgeFromOutside) {
  // Touches the plane only at the border point (1, 0, 0): closed rectangle -> hit at t = 0.5.
  const auto h = segment_plane(floor_plane(), Vec3(1, 0, 1), Vec3(1, 0, -1));
  ASSERT_TRUE(h.hit);
  EXPECT_DOUBLE_EQ(h.t, 0.5);
  // Passing just outside the corner, diagonally.
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(1.001, 0.501, 1), Vec3(1.001, 0.501, -1)).hit);
}

TEST(SegmentPlane, TiltedPlaneFarFromOrigin) {
  // A plane tilted 45 degrees about y, centred at (1e6, 2e6, -5e5).
  const Vec3 c(1e6, 2e6, -5e5);
  const Vec3 n = Vec3(1, 0, 1).normalized();
  const BoundedPlane p = make_bounded_plane(c, n, Vec3(1, 0, -1), Vec2(2.0, 1.0), 0.0);
  const Vec3 a = c + 3.0 * n + 0.5 * p.forward + 0.25 * p.right();
  const Vec3 b = c - 1.0 * n + 0.5 * p.forward + 0.25 * p.right();
  const auto h = segment_plane(p, a, b);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 0.75, 1e-9);
  const Vec3 a2 = c + 3.0 * n + 2.5 * p.forward;
  const Vec3 b2 = c - 1.0 * n + 2.5 * p.forward;
  EXPECT_FALSE(segment_plane(p, a2, b2).hit);
}

TEST(SegmentPlane, DegenerateSegment) {
  EXPECT_TRUE(segment_plane(floor_plane(), Vec3(0, 0, 0), Vec3(0, 0, 0)).hit);
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(0, 0, 1), Vec3(0, 0, 1)).hit);
}

}  // namespace
}  // namespace tecido
