#pragma once
/// Triangle-triangle intersection, the project's `core` engine: exact for every finite input.
#include "core/geometry/types.h"

namespace tecido {

/// True when the CLOSED triangles p and q share at least one point: crossing, touching at a
/// vertex or along an edge, a vertex on the other's face, coplanar overlap, a shared vertex
/// or edge all count. Degenerate triangles (repeated vertices, collinear vertices) are
/// treated as the segment or point they cover. The answer is exactly what exact arithmetic
/// gives, for every finite double input, and does not depend on the order of the vertices
/// nor on the order of p and q.
///
/// Method: Guigue & Devillers 2003, "Faster triangle-triangle intersection tests" (J. Graphics
/// Tools 8(1)): side of each vertex against the other triangle's plane, then two orientation
/// tests on canonically permuted vertices; coplanar pairs are tested in 2-D on the projection
/// that drops an axis along which the plane's normal is nonzero (decided exactly). All
/// decisions use the exact predicates of orient_predicates.h (Shewchuk 1997); the plane-side
/// tests share one cross product per triangle under the same static error bound.
bool tri_tri_intersect(const Triangle& p, const Triangle& q);

}  // namespace tecido
