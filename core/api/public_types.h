#pragma once
/// Between the public API's types (include/tecido/geometry.h) and core's own: the rectangle and
/// motion of the public headers as core's BoundedPlane and CcdQuery, and back. Used by the public
/// functions of core (core_api.cpp) and of the referee (reference/referee_api.cpp).
#include "core/geometry/bounded_plane.h"
#include "core/geometry/ccd/query.h"
#include "core/geometry/segment_plane.h"

#include <tecido/geometry.h>

namespace tecido::api {

inline BoundedPlane bounded_plane(const Rectangle& r) {
  BoundedPlane p;
  p.position = r.position;
  p.normal = r.normal;
  p.forward = r.forward;
  p.half_extents = Vec2(r.half_forward, r.half_right);
  return p;
}

inline CcdQuery ccd_query(const Motion& m) {
  return CcdQuery{m.kind == MotionKind::VertexFace ? CcdKind::VertexFace : CcdKind::EdgeEdge, m.x0, m.x1};
}

inline Motion motion(const CcdQuery& q) {
  return Motion{q.kind == CcdKind::VertexFace ? MotionKind::VertexFace : MotionKind::EdgeEdge, q.x0, q.x1};
}

}  // namespace tecido::api
