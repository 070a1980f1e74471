#pragma once
/// The seed's first triangle-triangle test, engine `core-rotation`, kept as written for
/// comparison (seed section 3.1.3, fig. 18, the "teste de rotação").
#include "core/geometry/types.h"

namespace tecido {

/// True when an edge of t1 crosses t2 or an edge of t2 crosses t1, by the seed's rotation
/// test in plain double arithmetic. For each edge (s, e) of one triangle: the signed plane
/// distances ds = n.(s - p1), de = n.(e - p1) (n = v12 x v13 of the other triangle) must not
/// be strictly on one side (ds*de <= 0, one end on the plane counts); the crossing point
/// pc = s + (e - s) ds/(ds - de) is inside when the angles from v12, v23, v31 to v1c, v2c,
/// v3c all open the same way, i.e. n.(vij x vic) has one sign for the three edges (zero
/// allowed: the border counts). The seed describes the edges of one triangle against the
/// other; like every edge-based test it also needs the converse (a triangle can pierce the
/// other with its interior only), so both directions are tried.
///
/// Known blind spots (by design, not fixed): coplanar pairs are never reported (an edge in
/// the other's plane has ds = de = 0 and is skipped, since the crossing point is undefined);
/// a degenerate other triangle (n = 0) is never hit; touching configurations (vertex on an
/// edge, edge on edge, shared vertex) and near-degenerate ones are decided by rounded signs,
/// so they come out either way; no tolerance, so the answer is scale-independent but not
/// exact. In general position it is right: on the benchmark's 10^5 random unit-cube pairs it
/// agrees with the exact `core` on every pair.
bool tri_tri_rotation(const Triangle& t1, const Triangle& t2);

}  // namespace tecido
