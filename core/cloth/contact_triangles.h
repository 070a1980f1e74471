#pragma once
/// The triangle pairs a continuous contact stands for, so that the responses written for
/// intersecting triangle pairs (the seed's edge modes, edge_response.h; GIA, gia.h) can act on
/// contacts found between frames (continuous_self_collision.h):
///   vertex-face (v, f):      (t, f) for every triangle t with corner v that shares no vertex with f;
///   edge-edge ((a,b),(c,d)): (t, u) for every triangle t with edge ab and u with edge cd that
///                            share no vertex.
/// A contact whose primitives have no such triangle (every triangle at v touches f) gives none.
#include "core/cloth/continuous_self_collision.h"
#include "core/cloth/self_collision.h"

#include <array>
#include <vector>

namespace tecido {

/// Incident triangles per vertex, for the mapping (CSR, built once per mesh).
struct VertexTriangles {
  std::vector<int> start;  ///< triangles of v: tris[start[v] .. start[v + 1])
  std::vector<int> tris;   ///< ascending per vertex
};
VertexTriangles build_vertex_triangles(int vertex_count, const std::vector<std::array<int, 3>>& triangles);

/// The pairs (i, j), i < j, of every contact in `c`, sorted and unique, into `out` (cleared).
void contact_triangle_pairs(const ContinuousContacts& c, const std::vector<std::array<int, 3>>& triangles,
                            const VertexTriangles& vt, std::vector<TrianglePair>& out);

}  // namespace tecido
