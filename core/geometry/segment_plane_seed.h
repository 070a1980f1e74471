#pragma once
/// The seed's segment-versus-bounded-plane test as written, in floating point: seed section
/// 3.1.1 (function DETECTACOLISÃO, fig. 7) with its two slips fixed (docs/design.md section 1):
/// a crossing needs the end points on different sides (or one on the plane), and the crossing
/// point must satisfy |forward.cp| <= hx and |right.cp| <= hy, centred on the plane's position.
/// Kept as its own engine ("core-seed") beside core's exact-decision test (segment_plane.h),
/// so that what rounding costs the seed's formulas stays measured.
#include "core/geometry/segment_plane.h"

namespace tecido {

/// Tests the segment p1 -> p2 against the closed rectangle of `plane` with the seed's formulas
/// in floating point: the sides and the crossing point are rounded, so a crossing within a
/// rounding of the border, or an end point within a rounding of the plane, is decided by
/// rounding. Touching counts; a segment lying in the plane hits at the first point inside the
/// rectangle (Liang-Barsky clip). Same contract as segment_plane() otherwise.
SegmentPlaneHit segment_plane_seed(const BoundedPlane& plane, const Vec3& p1, const Vec3& p2);

}  // namespace tecido
