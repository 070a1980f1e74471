#pragma once
/// Closest points between simple primitives, in floating point (Ericson, "Real-Time Collision
/// Detection", 2005, sections 5.1.5 and 5.1.9). Used to place a contact once a continuous test
/// has decided it, never to decide one.
#include "core/geometry/types.h"

namespace tecido {

/// Barycentric weights (wa, wb, wc), summing to 1 and each in [0, 1], of the point of the closed
/// triangle abc nearest to p (Ericson 5.1.5, by Voronoi regions). A degenerate triangle gives
/// the nearest point of its edges.
Vec3 closest_triangle_barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Parameters (s, t) in [0, 1]^2 of the closest points p0 + s (p1 - p0) and q0 + t (q1 - q0) of
/// two segments (Ericson 5.1.9; parallel segments: one of the closest pairs; a zero-length
/// segment is its point).
Vec2 closest_segment_params(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);

}  // namespace tecido
