// The exact referee on cases whose answer is known by construction: every coordinate is a
// dyadic rational (exact in binary), so touching, coplanar and on-the-border cases are really
// touching, coplanar and on the border.
#include "reference/exact_referee.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace tecido::reference {
namespace {

const Vec3 O(0, 0, 0), X(1, 0, 0), Y(0, 1, 0);
const Triangle T{O, X, Y};  // z = 0, legs along x and y
const double tiny = std::ldexp(1.0, -40);

Triangle shifted(Triangle t, const Vec3& d) {
  for (Vec3& v : t) v += d;
  return t;
}

void expect_symmetric(const Triangle& a, const Triangle& b, bool expected) {
  EXPECT_EQ(exact_tri_tri(a, b), expected);
  EXPECT_EQ(exact_tri_tri(b, a), expected);
}

TEST(ExactTriTri, SeparatedAndPiercing) {
  expect_symmetric(T, shifted(T, {0, 0, 1}), false);
  expect_symmetric(T, {Vec3(0.25, 0.25, -1), Vec3(0.25, 0.25, 1), Vec3(2, 2, 0.5)}, true);
}

TEST(ExactTriTri, VertexOnFaceTouchesAndLiftingItSeparates) {
  expect_symmetric(T, {Vec3(0.25, 0.25, 0), Vec3(0.25, 0.5, 1), Vec3(0.5, 0.25, 1)}, true);
  expect_symmetric(T, {Vec3(0.25, 0.25, tiny), Vec3(0.25, 0.5, 1), Vec3(0.5, 0.25, 1)}, false);
}

TEST(ExactTriTri, SharedVertexAndSharedEdgeTouch) {
  expect_symmetric(T, {O, Vec3(-1, 0, 1), Vec3(0, -1, 1)}, true);
  expect_symmetric(T, {O, X, Vec3(0.5, -1, 1)}, true);
}

TEST(ExactTriTri, VertexOnEdgeTouchesAndMovingItOffSeparates) {
  expect_symmetric(T, {Vec3(0.5, 0, 0), Vec3(0.5, -1, 1), Vec3(0.25, -1, 1)}, true);
  expect_symmetric(T, {Vec3(0.5, -tiny, 0), Vec3(0.5, -1, 1), Vec3(0.25, -1, 1)}, false);
}

TEST(ExactTriTri, SkewEdgesTouchingAtOnePoint) {
  // The second triangle's edge from (0.5,-0.5,0.5) to (0.5,0.5,-0.5) meets T's edge y = 0 at
  // (0.5, 0, 0) and nothing else of T.
  expect_symmetric(T, {Vec3(0.5, -0.5, 0.5), Vec3(0.5, 0.5, -0.5), Vec3(0.5, -1, -1)}, true);
  expect_symmetric(T, {Vec3(0.5, -0.5 - tiny, 0.5), Vec3(0.5, 0.5 - tiny, -0.5), Vec3(0.5, -1, -1)}, false);
}

TEST(ExactTriTri, Coplanar) {
  expect_symmetric(T, shifted(T, {0.25, 0.25, 0}), true);        // overlap
  expect_symmetric(T, shifted(T, {1, 1, 0}), false);             // disjoint
  expect_symmetric(T, {X, Vec3(2, 0, 0), Vec3(2, 1, 0)}, true);  // one common vertex
  expect_symmetric(T, {X, Y, Vec3(1, 1, 0)}, true);              // common edge
  expect_symmetric(T, {Vec3(0.125, 0.125, 0), Vec3(0.25, 0.125, 0), Vec3(0.125, 0.25, 0)}, true);  // inside
  expect_symmetric(T, {Vec3(0.5 + tiny, 0.5, 0), Vec3(1, 1, 0), Vec3(0.5, 0.5 + tiny, 0)},
                   false);  // past the hypotenuse
}

TEST(ExactTriTri, DegenerateTrianglesAreTheirPointSets) {
  const Vec3 c(0.25, 0.25, 0);
  expect_symmetric(T, {c, c, c}, true);  // point on the face
  expect_symmetric(T, {Vec3(0.25, 0.25, 0.5), Vec3(0.25, 0.25, 0.5), Vec3(0.25, 0.25, 0.5)}, false);
  expect_symmetric(T, {Vec3(0.25, 0.25, -1), Vec3(0.25, 0.25, 1), Vec3(0.25, 0.25, 0.5)},
                   true);  // segment piercing
  // Segment in T's plane passing outside the corner X: separated only by the segment's own
  // in-plane normal (a separating-axis test built for triangles lacks that axis).
  expect_symmetric(T, {Vec3(0.5, -0.5, 0), Vec3(1.5, 0.25, 0), Vec3(1, -0.125, 0)}, false);
  // Collinear corners listed out of order: the hull is the segment from the two extremes.
  expect_symmetric(T, {Vec3(0.5, 0.5, 1), Vec3(0.5, 0.5, -1), Vec3(0.5, 0.5, 0.5)}, true);
  expect_symmetric({O, X, X}, {Vec3(0.5, -1, 0), Vec3(0.5, 1, 0), Vec3(0.5, 1, 0)},
                   true);  // segments crossing
  expect_symmetric({O, X, X}, {Vec3(0.5, 1, 0), Vec3(0.5, 2, 0), Vec3(0.5, 2, 0)}, false);  // segments apart
  expect_symmetric({X, X, X}, {X, X, X}, true);
  expect_symmetric({X, X, X}, {Y, Y, Y}, false);
  expect_symmetric({O, X, X}, {Vec3(0.5, 0, 0), Vec3(0.5, 0, 0), Vec3(0.5, 0, 0)}, true);  // point on segment
}

TEST(ExactTriTri, RejectsNonFiniteInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(exact_tri_tri(T, {Vec3(nan, 0, 0), X, Y}), std::domain_error);
  EXPECT_THROW(exact_tri_tri({Vec3(INFINITY, 0, 0), X, Y}, T), std::domain_error);
}

// Segment versus bounded plane. Default plane: centre 0, normal z, forward x, hx = 1, hy = 0.5.
BoundedPlane unit_plane() {
  BoundedPlane p;
  p.half_extents = Vec2(1, 0.5);
  return p;
}

void expect_hit(const ExactSegmentPlane& r, double t) {
  EXPECT_TRUE(r.hit);
  EXPECT_EQ(r.t, t);
  EXPECT_TRUE(r.t_is_exact);
}

TEST(ExactSegmentPlane, CrossingsInsideAndOnTheBorder) {
  const BoundedPlane p = unit_plane();
  expect_hit(exact_segment_plane(p, {0, 0, 1}, {0, 0, -3}), 0.25);
  expect_hit(exact_segment_plane(p, {1, 0.25, 1}, {1, 0.25, -1}), 0.5);     // on the edge x = hx
  expect_hit(exact_segment_plane(p, {1, 0.5, 1}, {1, 0.5, -1}), 0.5);       // on the corner
  expect_hit(exact_segment_plane(p, {-1, -0.5, -3}, {-1, -0.5, 1}), 0.75);  // opposite corner, upwards
  EXPECT_FALSE(exact_segment_plane(p, {1 + tiny, 0.5, 1}, {1 + tiny, 0.5, -1}).hit);
  EXPECT_FALSE(exact_segment_plane(p, {0, -0.5 - tiny, 1}, {0, -0.5 - tiny, -1}).hit);
}

// A negative half extent is an empty rectangle: no segment meets it, not even one through the centre
// (fuzz_plane_vs_exact's regress_negative_half_extent: [-h, h] with h < 0 was taken as [h, -h]).
TEST(ExactSegmentPlane, NegativeHalfExtentIsAnEmptyRectangle) {
  BoundedPlane p = unit_plane();
  p.half_extents.x() = -1;
  EXPECT_FALSE(exact_segment_plane(p, {0, 0, 1}, {0, 0, -1}).hit);
  EXPECT_FALSE(exact_segment_plane(p, {-2, 0, 0}, {2, 0, 0}).hit);  // in the plane, across it
  p = unit_plane();
  p.half_extents.y() = -0.5;
  EXPECT_FALSE(exact_segment_plane(p, {0.5, 0, 1}, {0.5, 0, -1}).hit);
  p.half_extents.y() = 0.0;  // a segment of zero width: still met on the line b = 0
  expect_hit(exact_segment_plane(p, {0.5, 0, 1}, {0.5, 0, -1}), 0.5);
}

TEST(ExactSegmentPlane, RationalFractionIsRoundedToNearest) {
  const ExactSegmentPlane r = exact_segment_plane(unit_plane(), {0, 0, 1}, {0, 0, -2});
  EXPECT_TRUE(r.hit);
  EXPECT_EQ(r.t, 1.0 / 3.0);  // correctly rounded division
  EXPECT_FALSE(r.t_is_exact);

  // t = 1 - 2^-54 exactly, halfway between 1 - 2^-53 and 1: ties go to the even significand, 1.
  BoundedPlane p = unit_plane();
  p.position.z() = std::ldexp(1.0, -54);
  const ExactSegmentPlane tie = exact_segment_plane(p, {0, 0, 1}, {0, 0, 0});
  EXPECT_TRUE(tie.hit);
  EXPECT_EQ(tie.t, 1.0);
  EXPECT_FALSE(tie.t_is_exact);
}

TEST(ExactSegmentPlane, EndPointsOnThePlane) {
  const BoundedPlane p = unit_plane();
  expect_hit(exact_segment_plane(p, {1, 0, 1}, {1, 0, 0}), 1.0);      // ends exactly on the border
  expect_hit(exact_segment_plane(p, {0.5, 0, 0}, {0.5, 0, 1}), 0.0);  // starts on the plane, leaves
  EXPECT_FALSE(exact_segment_plane(p, {2, 0, 1}, {2, 0, 0}).hit);     // ends on the plane, outside
  EXPECT_FALSE(exact_segment_plane(p, {0, 0, 1}, {0, 0, tiny}).hit);  // stops just short
}

TEST(ExactSegmentPlane, SegmentInThePlane) {
  const BoundedPlane p = unit_plane();
  expect_hit(exact_segment_plane(p, {-3, 0, 0}, {1, 0, 0}), 0.5);      // enters at x = -1
  expect_hit(exact_segment_plane(p, {0.5, 0, 0}, {3, 0, 0}), 0.0);     // starts inside
  expect_hit(exact_segment_plane(p, {-3, 0.5, 0}, {1, 0.5, 0}), 0.5);  // slides along the edge y = hy
  expect_hit(exact_segment_plane(p, {-3, 0, 0}, {-1, 0, 0}), 1.0);     // ends on the border
  expect_hit(exact_segment_plane(p, {-3, -3, 0}, {1, 1, 0}), 0.625);   // enters through y = -hy
  expect_hit(exact_segment_plane(p, {0, 1.5, 0}, {2, -0.5, 0}), 0.5);  // touches the corner (1, 0.5) only
  EXPECT_FALSE(exact_segment_plane(p, {-3, 0.5 + tiny, 0}, {1, 0.5 + tiny, 0}).hit);
  EXPECT_FALSE(exact_segment_plane(p, {0, 1.5 + tiny, 0}, {2, -0.5 + tiny, 0}).hit);  // misses the corner
}

TEST(ExactSegmentPlane, DegenerateSegments) {
  const BoundedPlane p = unit_plane();
  expect_hit(exact_segment_plane(p, {0.5, 0.25, 0}, {0.5, 0.25, 0}), 0.0);
  expect_hit(exact_segment_plane(p, {1, 0.5, 0}, {1, 0.5, 0}), 0.0);
  EXPECT_FALSE(exact_segment_plane(p, {0.5, 0.25, 1}, {0.5, 0.25, 1}).hit);
  EXPECT_FALSE(exact_segment_plane(p, {3, 0.25, 0}, {3, 0.25, 0}).hit);
}

TEST(ExactSegmentPlane, ParallelAboveMisses) {
  EXPECT_FALSE(exact_segment_plane(unit_plane(), {-3, 0, 1}, {3, 0, 1}).hit);
  EXPECT_FALSE(exact_segment_plane(unit_plane(), {-3, 0, tiny}, {3, 0, tiny}).hit);
}

TEST(ExactSegmentPlane, HalfExtentsFollowForwardAndRight) {
  // normal x, forward y, so right = normal x forward = z: hx bounds y, hy bounds z.
  BoundedPlane p;
  p.normal = Vec3(1, 0, 0);
  p.forward = Vec3(0, 1, 0);
  p.half_extents = Vec2(1, 0.5);
  p.position = Vec3(0.5, 0.25, -0.25);
  expect_hit(exact_segment_plane(p, {-1, 1.125, 0.125}, {1, 1.125, 0.125}), 0.75);  // y - 0.25 = 0.875
  EXPECT_FALSE(exact_segment_plane(p, {-1, 0.5, 0.5}, {1, 0.5, 0.5}).hit);          // z + 0.25 = 0.75 > hy
  expect_hit(exact_segment_plane(p, {1, 1.25, 0.25}, {0, 1.25, 0.25}), 0.5);        // corner, from +x
}

TEST(ExactSegmentPlane, UsesTheStoredVectorsExactly) {
  // A normal that is not exactly unit in binary: the referee uses the stored doubles as they
  // are (s = N.(p - P) exactly), so the point P + N (rounded) is strictly on the + side and
  // P - N on the - side, and the crossing is at the centre.
  BoundedPlane p =
      make_bounded_plane(Vec3(0.1, 0.2, 0.3), Vec3(0.3, -0.4, 1.2), Vec3(1, 0.2, 0), Vec2(0.7, 0.3), 0);
  const ExactSegmentPlane r = exact_segment_plane(p, p.position + p.normal, p.position - p.normal);
  EXPECT_TRUE(r.hit);
  EXPECT_NEAR(r.t, 0.5, 1e-15);
  // Offsets well inside and well outside the rectangle along the (rounded) right vector.
  const Vec3 in = p.position + 0.25 * p.right(), out = p.position + 0.35 * p.right();
  EXPECT_TRUE(exact_segment_plane(p, in + p.normal, in - p.normal).hit);
  EXPECT_FALSE(exact_segment_plane(p, out + p.normal, out - p.normal).hit);
}

TEST(ExactSegmentPlane, RejectsNonFiniteInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(exact_segment_plane(unit_plane(), {nan, 0, 1}, {0, 0, -1}), std::domain_error);
  BoundedPlane p = unit_plane();
  p.half_extents.x() = INFINITY;
  EXPECT_THROW(exact_segment_plane(p, {0, 0, 1}, {0, 0, -1}), std::domain_error);
}

}  // namespace
}  // namespace tecido::reference
