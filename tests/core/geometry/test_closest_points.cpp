// Closest points on a triangle and between segments, hand-worked by Voronoi region.
#include "core/geometry/closest_points.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

const Vec3 A(0, 0, 0), B(3, 0, 0), C(0, 3, 0);

TEST(ClosestPoints, TriangleRegions) {
  // Above the interior: the projection (1, 1, 0) = A/3 + B/3 + C/3.
  const Vec3 in = closest_triangle_barycentric(Vec3(1, 1, 5), A, B, C);
  EXPECT_NEAR(in[0], 1.0 / 3, 1e-15);
  EXPECT_NEAR(in[1], 1.0 / 3, 1e-15);
  EXPECT_NEAR(in[2], 1.0 / 3, 1e-15);
  EXPECT_EQ(closest_triangle_barycentric(Vec3(-1, -1, 2), A, B, C), Vec3(1, 0, 0));  // vertex A
  EXPECT_EQ(closest_triangle_barycentric(Vec3(5, -1, 0), A, B, C), Vec3(0, 1, 0));   // vertex B
  const Vec3 ab = closest_triangle_barycentric(Vec3(1, -2, 1), A, B, C);             // edge AB at (1, 0, 0)
  EXPECT_NEAR(ab[1], 1.0 / 3, 1e-15);
  EXPECT_EQ(ab[2], 0.0);
  const Vec3 bc = closest_triangle_barycentric(Vec3(2, 2, 0), A, B, C);  // edge BC at (1.5, 1.5, 0)
  EXPECT_EQ(bc[0], 0.0);
  EXPECT_NEAR(bc[1], 0.5, 1e-15);
}

TEST(ClosestPoints, Segments) {
  // Perpendicular, crossing at their midpoints one unit apart.
  const Vec2 st = closest_segment_params(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 1), Vec3(0, 1, 1));
  EXPECT_NEAR(st[0], 0.5, 1e-15);
  EXPECT_NEAR(st[1], 0.5, 1e-15);
  // The second segment beyond the first's end: clamped to s = 1.
  const Vec2 end = closest_segment_params(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, -1, 0), Vec3(3, 1, 0));
  EXPECT_EQ(end[0], 1.0);
  EXPECT_NEAR(end[1], 0.5, 1e-15);
  // A point against a segment.
  const Vec2 pt = closest_segment_params(Vec3(0.25, 5, 0), Vec3(0.25, 5, 0), Vec3(0, 0, 0), Vec3(1, 0, 0));
  EXPECT_NEAR(pt[1], 0.25, 1e-15);
}

}  // namespace
}  // namespace tecido
