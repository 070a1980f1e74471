#pragma once
/// The cheapest certified rejection of a continuous collision query: swept bounding boxes.
#include "core/geometry/ccd_query.h"

namespace tecido {

/// True when the swept axis-aligned boxes of the two primitives of q are disjoint along some
/// axis. A primitive's swept box is the box of its points at t = 0 and t = 1; it contains the
/// primitive at every t in [0, 1] (each point moves on the segment between its two
/// positions, and the box is convex), so disjoint boxes mean the primitives never touch.
/// Exact (comparisons only). Boxes are closed: touching boxes are not disjoint. Inputs must
/// be finite (a NaN coordinate may be ignored by the comparisons).
inline bool ccd_swept_boxes_disjoint(const CcdQuery& q) {
  // Vertex-face: point 0 against points 1..3; edge-edge: points 0, 1 against points 2, 3.
  const int split = q.kind == CcdKind::VertexFace ? 1 : 2;
  for (int c = 0; c < 3; ++c) {
    double alo = q.x0[0][c], ahi = alo;
    for (int i = 0; i < split; ++i) {
      for (const double v : {q.x0[i][c], q.x1[i][c]}) {
        alo = v < alo ? v : alo;
        ahi = v > ahi ? v : ahi;
      }
    }
    double blo = q.x0[split][c], bhi = blo;
    for (int i = split; i < 4; ++i) {
      for (const double v : {q.x0[i][c], q.x1[i][c]}) {
        blo = v < blo ? v : blo;
        bhi = v > bhi ? v : bhi;
      }
    }
    if (ahi < blo || bhi < alo) return true;
  }
  return false;
}

}  // namespace tecido
