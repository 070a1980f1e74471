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

/// Batched early rejection for eight pairs at once (AVX-512F, chosen at run time; see
/// tri_tri_reject8_available). Lane k is the pair (p_k, q_k); pv[i][k] and qv[i][k] are the
/// offsets 3 * vertex of corner i of p_k and q_k in x, the vertex coordinates (x, y, z per
/// vertex). Returns bit k set when the three corners of p_k are certified strictly on one
/// side of q_k's plane: the first step of tri_tri_intersect, with the same static filter, so a
/// set bit means tri_tri_intersect(p_k, q_k) is false (a clear bit decides nothing: call it).
/// The filter's operations are those of the scalar code, lane-wise, without contraction.
unsigned tri_tri_reject8(const double* x, const int (&pv)[3][8], const int (&qv)[3][8]);
/// True when this CPU runs tri_tri_reject8 (AVX-512F); otherwise it must not be called.
bool tri_tri_reject8_available();

}  // namespace tecido
