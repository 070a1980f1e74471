#pragma once
/// Segment versus bounded plane, seed section 3.1.1 (function DETECTACOLISÃO, fig. 7), with
/// the seed's two slips fixed (docs/design.md section 1): a crossing needs the end points on
/// different sides (or one on the plane), and the crossing point must satisfy
/// |forward.cp| <= hx and |right.cp| <= hy, centred on the plane's position.
#include "core/geometry/bounded_plane.h"

#include <optional>

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
/// (t = 0 if p1 is inside). Floating point; the exact referee lives in reference/.
SegmentPlaneHit segment_plane(const BoundedPlane& plane, const Vec3& p1, const Vec3& p2);

}  // namespace tecido
