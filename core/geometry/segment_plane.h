#pragma once
/// Segment versus bounded plane, seed section 3.1.1 (function DETECTACOLISÃO, fig. 7), with
/// the seed's two slips fixed (docs/design.md section 1): a crossing needs the end points on
/// different sides (or one on the plane), and the crossing point must satisfy
/// |forward.cp| <= hx and |right.cp| <= hy, centred on the plane's position.
///
/// The decision (hit or not) is exact for the doubles given: it is the answer of the seed's
/// formulas evaluated without rounding on the stored position P, normal n, forward f, half
/// extents and end points, with right r = n x f taken exactly (not the rounded plane.right()),
/// n and f not assumed exactly unit or orthogonal; the exact referee (reference/) defines the
/// same thing in rationals. With d_i = p_i - P, s_i = n.d_i, a_i = f.d_i, b_i = r.d_i:
///  - s1, s2 of the same strict sign: miss;
///  - otherwise, unless both are 0, the crossing point's coordinates are
///    a = (s1 a2 - s2 a1) / (s1 - s2) and b likewise, so |a| <= hx is
///    hx |s1 - s2| - |s1 a2 - s2 a1| >= 0: a sign of a polynomial in the inputs (degree 4;
///    degree 5 for b, whose r is itself of degree 2);
///  - s1 = s2 = 0 (the segment lies in the plane): the 2-D segment (a, b) against the closed
///    rectangle by separating axes (the rectangle's two axes and the segment's normal), again
///    signs of polynomials (degree <= 5).
/// Each sign is first taken from a floating-point evaluation with a rigorous error bound
/// (Shewchuk 1997's filter idea; the bound is derived in segment_plane.cpp), and only when
/// that cannot decide from exact dyadic arithmetic (core/geometry/exact_dyadic.h), so the
/// answer is exact for every finite input, from 1e-300 to 1e300 and beyond. The crossing
/// fraction t stays a floating-point value. The seed's floating-point test as written is
/// segment_plane_seed() (segment_plane_seed.h).
#include "core/geometry/bounded_plane.h"

#include <cstdint>

namespace tecido {

struct SegmentPlaneHit {
  bool hit = false;
  /// Fraction along the segment p1 -> p2 of the first point on the closed rectangle, in [0, 1];
  /// meaningful only when hit.
  double t = 0.0;
};

/// Tests the segment p1 -> p2 against the closed rectangle of `plane`. Touching counts: an end
/// point on the plane inside the rectangle, or a crossing exactly on the rectangle's border,
/// is a hit. A segment lying in the plane hits at the first point inside the rectangle
/// (t = 0 if p1 is inside). `hit` is exact for every finite input (see the file comment);
/// t = s1 / (s1 - s2) in floating point (0 or 1 when an end point is exactly on the plane;
/// in the plane, the entry of a Liang-Barsky clip). NaN or infinite input, or a negative half
/// extent (an empty rectangle): no hit. Method: seed section 3.1.1, exact signs by a filtered
/// floating-point evaluation and an exact dyadic fallback.
SegmentPlaneHit segment_plane(const BoundedPlane& plane, const Vec3& p1, const Vec3& p2);

/// Number of calls, on the calling thread, that the floating-point filter could not decide and
/// that took the exact path. A diagnostic for tests and benchmarks; it never resets by itself.
std::uint64_t segment_plane_exact_path_count();

namespace detail {

/// segment_plane without the filter: every sign in exact dyadic arithmetic. Counts towards
/// segment_plane_exact_path_count(). Exposed so that tests can compare the two paths.
SegmentPlaneHit segment_plane_exact(const BoundedPlane& plane, const Vec3& p1, const Vec3& p2);

}  // namespace detail

}  // namespace tecido
