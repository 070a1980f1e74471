#pragma once
/// Connectivity of a triangle mesh over a vertex array, computed once from the triangles
/// (positions play no part): the unique edges, each triangle's edges, vertex neighbours, and
/// each vertex's distance to the mesh boundary in edge hops. Used by the self-collision
/// responses: global intersection analysis floods over edges (gia.h), the seed's edge modes
/// need "the neighbour nearest the border" (edge_response.h, seed section 3.1.3, fig. 20).
#include <array>
#include <cstdint>
#include <vector>

namespace tecido {

struct MeshTopology {
  int vertex_count = 0;                       ///< size of the vertex array the triangles index
  std::vector<std::array<int, 2>> edges;      ///< unique edges (u < v), sorted lexicographically
  std::vector<std::array<int, 3>> tri_edges;  ///< per triangle: ids of edges (v0v1, v1v2, v2v0)
  std::vector<int> edge_triangles;            ///< per edge: number of incident triangles
  std::vector<int> adj_start;                 ///< CSR: neighbours of v are adj[adj_start[v] .. adj_start[v+1])
  std::vector<int> adj;                       ///< neighbour vertex ids, ascending per vertex
  std::vector<int> adj_edge;                  ///< edge id joining v and adj[k], parallel to adj
  std::vector<std::uint8_t> used;             ///< 1 when the vertex belongs to some triangle
  /// Edge hops from the vertex to the nearest boundary vertex (a vertex on an edge that has
  /// exactly one incident triangle); 0 on the boundary; -1 for unused vertices and for
  /// vertices whose connected piece has no boundary (a closed surface).
  /// On the cloth builder's grid (core/scene/cloth_builder.h) this equals
  /// min(r, c, rows-1-r, cols-1-c) for node (r, c): every mesh edge changes r and c by at most
  /// one, and the straight path to the nearest side achieves the bound.
  std::vector<int> border_distance;
};

/// Builds the topology of `triangles` (indices into a vertex array of `vertex_count`
/// entries). Preconditions: every index in [0, vertex_count), no repeated index in a triangle.
/// Deterministic: edges are numbered in sorted order, neighbours ascend.
MeshTopology build_mesh_topology(int vertex_count, const std::vector<std::array<int, 3>>& triangles);

}  // namespace tecido
