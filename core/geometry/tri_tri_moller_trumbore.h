#pragma once
/// The seed's second triangle-triangle test, engine `core-mt` (seed section 3.1.3): the
/// Möller-Trumbore ray-triangle test applied to triangle edges.
#include "core/geometry/types.h"

namespace tecido {

/// Möller & Trumbore 1997, "Fast, Minimum Storage Ray/Triangle Intersection" (J. Graphics
/// Tools 2(1)), on the segment o -> o + dir (t in [0, 1]), plain double, with the paper's
/// culling-free epsilon: a hit needs |det| >= 1e-6 (det = e1 . (dir x e2), an ABSOLUTE
/// threshold), 0 <= u <= 1, 0 <= v, u + v <= 1 (borders count) and 0 <= t <= 1.
bool segment_triangle_moller_trumbore(const Vec3& o, const Vec3& dir, const Triangle& t);

/// The seed's rule, as written: "each edge of the first triangle is tested against the
/// second; if a collision is detected, the converse (edges of the second against the first)
/// must be tested as well; if both tests detect a collision, the triangles collide". So this
/// returns (some edge of t1 hits t2) AND (some edge of t2 hits t1). The seed motivates the
/// double test by Möller-Trumbore working on infinite lines; here the edges are segments
/// (t in [0, 1]), so the second test only removes answers.
///
/// Known blind spots: (1) the AND misses every pair where only one triangle's edges pierce
/// the other, e.g. a small triangle stabbing through the middle of a large one (a common
/// configuration: 46% of the intersecting pairs among the benchmark's 10^5 random unit-cube
/// pairs, 12915 of 28180); (2) the
/// absolute epsilon 1e-6 on det, a volume-like quantity (length^3), rejects every edge of a
/// small triangle (edges ~1e-2 give det ~1e-6) and edges nearly parallel to the plane; so
/// coplanar pairs are never reported and results depend on the scene's scale and units;
/// (3) touching configurations are decided by rounded arithmetic; degenerate triangles have
/// det = 0 and are never hit.
bool tri_tri_moller_trumbore(const Triangle& t1, const Triangle& t2);

}  // namespace tecido
