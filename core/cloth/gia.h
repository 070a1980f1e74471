#pragma once
/// Global intersection analysis (GIA) of a self-intersecting cloth, after Baraff, Witkin and
/// Kass 2003, "Untangling cloth" (ACM TOG 22(3)), as the seed describes it (section 3.1.3,
/// fig. 19): from the intersection curve, flood the mesh on both sides; the side whose flood
/// ends first (the smaller region) is the one on the wrong side; the regions on the two sheets
/// that have passed through each other are then pulled back through each other.
///
/// Discrete form used here (history-free, positions of the current frame only):
///  1. The intersection curve crosses a mesh edge exactly where that edge pierces a triangle
///     of the other sheet. An edge is CUT when it meets (closed segment vs closed triangle,
///     exact orientation predicates) a triangle of an intersecting pair it is not incident
///     to. An edge lying in the other triangle's plane is not cut (coplanar contact has no
///     crossing curve).
///  2. Vertices are flooded over uncut edges: connected components.
///  3. For each cut edge (u, v): when u and v fall in different components, the smaller
///     component (vertex count) is a WRONG-SIDE region; equal sizes are ambiguous (no region).
///     When u and v fall in the SAME component, the curve does not separate the mesh there:
///     the flood from one side reaches the other and covers the whole piece. This is the
///     seed's failing case (an intersection reaching the cloth's border, whose curve is open);
///     such edges are counted as `unseparated_cut_edges`.
///  4. Pairing: for each intersecting pair (t1, t2), every region touching t1 (owning one of
///     its vertices) is paired with every region touching t2. A region is pulled toward the
///     centroid of its partner regions' vertices; with no partner region (the other sheet's
///     curve encloses no vertex, or cannot be separated) toward the centroid of the vertices of
///     the opposite triangles of its pairs. Pulling each region toward its partner reverses
///     the pass-through (BWK: "the points inside the region attract their buddies and pull
///     back through"; BWK do it inside their proximity response, which this engine does not
///     have, so the attraction acts on whole regions).
///  5. A pair is RESOLVED when one of its triangles touches a region with a nonzero pull.
///     An unresolved pair is where GIA fails; `gia+edge3` hands those to the seed's edge mode 3.
#include "core/cloth/mesh_topology.h"
#include "core/cloth/self_collision.h"

#include <cstdint>
#include <vector>

namespace tecido {

struct GiaResult {
  std::vector<std::uint8_t> cut;           ///< per mesh edge: 1 when cut by the intersection
  std::vector<int> component;              ///< per vertex: component over uncut edges, -1 if unused
  std::vector<int> component_size;         ///< vertices per component
  std::vector<std::uint8_t> wrong_side;    ///< per component: 1 = a wrong-side region
  std::vector<Vec3> pull;                  ///< per component: unit pull direction, zero if none
  std::vector<int> regions;                ///< ids of wrong-side components, ascending
  std::vector<std::uint8_t> pair_resolved; ///< per input pair: 1 when GIA handles it
  int cut_edges = 0;
  int unseparated_cut_edges = 0;           ///< cut edges whose two ends stay connected (seed's failing case)
  int ambiguous_cut_edges = 0;             ///< cut edges between two components of equal size
  int unresolved_pairs = 0;                ///< pairs GIA leaves alone

  /// Workspace reused between calls (not part of the result).
  struct Work {
    std::vector<int> queue;
    std::vector<Vec3> centroid, fallback_sum;
    std::vector<int> fallback_count;
    std::vector<std::array<int, 2>> links;
  } work;
};

/// True when the closed segment p-q meets the closed triangle t in a point, the segment not
/// lying in t's plane. Exact (orient3d signs, Shewchuk 1997).
bool segment_pierces_triangle(const Vec3& p, const Vec3& q, const Triangle& t);

/// Runs steps 1-5 above for the intersecting `pairs` (as returned by the detector) of the mesh
/// `triangles` with topology `topo` at positions x. Reuses `out`'s buffers (no allocation once
/// warmed up, apart from growth).
void analyse_intersections(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles,
                           const MeshTopology& topo, const std::vector<TrianglePair>& pairs, GiaResult& out);

}  // namespace tecido
