#pragma once
/// A continuous collision query between two primitives moving over one time step, the unit of
/// continuous collision detection (Bridson, Fedkiw and Anderson 2002; the benchmark of Wang,
/// Ferguson, Schneider, Jiang, Attene and Panozzo, ACM TOG 2021, uses the same form):
///   vertex-face: x[0] is the vertex, x[1], x[2], x[3] the triangle's corners;
///   edge-edge:   x[0]-x[1] is the first segment, x[2]-x[3] the second.
/// Every point moves linearly, p(t) = (1 - t) x0 + t x1 for t in [0, 1]. The primitives are
/// closed: touching counts as contact. Degenerate motion (coplanar throughout, parallel or
/// collinear edges, zero-length edges, zero-area triangles) is part of the domain.
/// The file format and command are in docs/design.md section 3 (`tecido ccd`).
#include "core/geometry/types.h"

#include <array>

namespace tecido {

enum class CcdKind { VertexFace, EdgeEdge };

/// "vertex-face" or "edge-edge" (the names of the file format).
inline const char* ccd_kind_name(CcdKind k) { return k == CcdKind::VertexFace ? "vertex-face" : "edge-edge"; }

struct CcdQuery {
  CcdKind kind = CcdKind::VertexFace;
  std::array<Vec3, 4> x0;  ///< positions at t = 0
  std::array<Vec3, 4> x1;  ///< positions at t = 1
};

/// An engine's answer to a CcdQuery: whether the primitives touch at some t in [0, 1], and the
/// earliest such t (meaningful only when hit; a conservative engine may report a time at or
/// before the true one, and says so in its own documentation).
struct CcdAnswer {
  bool hit = false;
  double toi = 0.0;
};

}  // namespace tecido
