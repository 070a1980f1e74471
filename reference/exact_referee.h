#pragma once
/// The exact referee: triangle-triangle and segment-versus-bounded-plane answers computed with
/// exact arithmetic (CGAL 5.5, GMP rationals) on the given doubles, taken as exact numbers. It
/// settles disagreements between the core and the other reference engines (docs/design.md section 1).
/// Only core types cross this header; CGAL stays inside exact_referee.cpp.
#include "core/geometry/bounded_plane.h"
#include "core/geometry/types.h"

namespace tecido::reference {

/// Whether the two closed triangles share at least one point (touching counts), decided
/// exactly. Method: CGAL::do_intersect with Exact_predicates_inexact_constructions_kernel
/// (filtered exact predicates; Guigue-Devillers 2003 for Triangle_3/Triangle_3).
/// Degenerate triangles, which CGAL's Triangle_3 rejects by precondition, are replaced by the
/// point set they really are, decided exactly: three equal corners -> Point_3; collinear
/// corners -> Segment_3 between the lexicographically smallest and largest corner (collinear
/// points are ordered along their line the same way lexicographically, so these are the two
/// extremes). Any mix of Triangle_3/Segment_3/Point_3 is then passed to CGAL::do_intersect.
/// Throws std::domain_error if a coordinate is NaN or infinite.
bool exact_tri_tri(const Triangle& a, const Triangle& b);

/// The referee's answer for a segment against a bounded plane.
struct ExactSegmentPlane {
  bool hit = false;
  /// Fraction along p1 -> p2 of the first point of the segment on the closed rectangle: the
  /// exact rational rounded to the nearest double (ties to even). 0 when !hit.
  double t = 0.0;
  /// True when `t` equals the exact rational (no rounding happened).
  bool t_is_exact = true;
};

/// Segment p1 -> p2 against the closed rectangle of `plane`, decided exactly.
///
/// Definition (the core's floating-point formulas of core/geometry/bounded_plane.h, evaluated
/// without rounding): every stored double (position P, normal N, forward F, half extents
/// hx, hy, end points) is taken as the exact rational it represents, and
///   R    = N x F                       (exact cross product, NOT the rounded plane.right())
///   s(p) = N.(p - P)                   side of the plane (0 = on the plane)
///   a(p) = F.(p - P),  b(p) = R.(p - P)
///   p is in the rectangle  iff  s(p) = 0 and |a(p)| <= hx and |b(p)| <= hy.
/// N and F are not required to be exactly unit or orthogonal: the rectangle is whatever these
/// exact expressions describe, which is what the core's test approximates; the core's rounding
/// of right() and of the dot products is part of what this referee measures.
///   - s1, s2 of the same strict sign: miss.
///   - s1 = s2 = 0 (segment in the plane, including a degenerate segment p1 = p2 on it):
///     a and b are affine in t, the constraints give an interval of t within [0, 1]; hit at its
///     lower end (t = 0 when p1 is inside), miss when it is empty.
///   - otherwise (a strict sign change, or exactly one end on the plane): the single point on
///     the plane is at t = s1 / (s1 - s2) (rational); hit iff it is in the rectangle.
/// A degenerate segment off the plane is a miss; so is every segment when a half extent is
/// negative (the rectangle is empty). Method: plain rational arithmetic with
/// CGAL::Gmpq (GMP mpq). Throws std::domain_error if an input is NaN or infinite.
ExactSegmentPlane exact_segment_plane(const BoundedPlane& plane, const Vec3& p1, const Vec3& p2);

}  // namespace tecido::reference
