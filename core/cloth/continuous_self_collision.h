#pragma once
/// Continuous self-collision of one triangle mesh moving linearly between two frames: every
/// vertex-face pair (the vertex not a corner of the face) and every edge-edge pair (edges
/// sharing no vertex) that may touch at some time of the motion, according to a continuous
/// collision test (default: core's, core/geometry/ccd.h: no false negatives, near misses within
/// its distance tolerance may be included). Discrete self-collision (self_collision.h) looks at
/// one instant; a cloth can pass through itself within one step with both frames clean.
///
/// Two drivers with identical output (for core's test, and for any test that answers miss
/// when two primitives' swept or kinetic boxes are disjoint, as every test should: such
/// primitives cannot touch; the broad phase never asks it about them):
///  - continuous_self_collision_brute: every vertex-face and edge-edge pair, O(n^2) (engine
///    `core-brute`, the reference for tests);
///  - ContinuousSelfCollisionDetector: each vertex and each edge is owned by one triangle (the
///    first that has it), and a primitive pair is tested only from the triangle pair of its
///    owners, so each pair is tested once. Owners that share a vertex (neighbours) are known
///    from the topology: their feature pairs are listed once at construction. The others come
///    from the triangle box tree (triangle_bvh.h) refitted on swept boxes (each triangle's box
///    over both frames, which contains its owned features' at every time, in a frame moving
///    with the mesh's mean displacement, which changes no contact), pairs whose kinetic boxes
///    never meet dropped. Then the primitives' own swept and kinetic boxes (the first stages
///    of core's test, ccd_pipeline.h, on the same numbers: the same decisions), then the test.
/// Output: vertex_face as (v, f), 0-based vertex and face indices, sorted; edge_edge as
/// ((a, b), (c, d)) with a < b, c < d and (a, b) < (c, d), sorted lexicographically.
/// Positions must be finite; both frames have the same size; no triangle repeats an index.
#include "core/geometry/ccd_query.h"

#include "core/cloth/triangle_bvh.h"

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace tecido {

using MeshEdge = std::array<int, 2>;                  ///< (a, b), a < b
using EdgeEdgePair = std::array<MeshEdge, 2>;         ///< ((a, b), (c, d)), (a, b) < (c, d)
using VertexFacePair = std::array<int, 2>;            ///< (vertex, face)

struct ContinuousContacts {
  std::vector<VertexFacePair> vertex_face;
  std::vector<EdgeEdgePair> edge_edge;
  bool operator==(const ContinuousContacts& o) const { return vertex_face == o.vertex_face && edge_edge == o.edge_edge; }
};

/// A continuous collision test: core's ccd by default.
using CcdTest = CcdAnswer (*)(const CcdQuery&);

/// The query of vertex v against face `tri` (its corners, in order) moving from x0 to x1.
CcdQuery vertex_face_query(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, int v, const std::array<int, 3>& tri);
/// The query of edges e and f moving from x0 to x1.
CcdQuery edge_edge_query(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, const MeshEdge& e, const MeshEdge& f);

/// Every pair the test says may touch, by trying all pairs (vertex-face: every vertex used by
/// some triangle against every face without it; edge-edge: every two mesh edges without a
/// shared vertex). Sorted as described above.
ContinuousContacts continuous_self_collision_brute(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                                                   const std::vector<std::array<int, 3>>& triangles,
                                                   CcdTest test = nullptr);

/// Broad phase plus the test; detect() returns exactly what continuous_self_collision_brute
/// returns for the same frames and test. No allocation per call once warmed up.
class ContinuousSelfCollisionDetector {
 public:
  /// Keeps a copy of the triangles; builds the tree from x_build (e.g. the rest shape).
  ContinuousSelfCollisionDetector(const std::vector<std::array<int, 3>>& triangles, const std::vector<Vec3>& x_build,
                                  CcdTest test = nullptr);

  /// The pairs that may touch during the motion from x0 to x1 (valid until the next call).
  const ContinuousContacts& detect(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);

  /// Triangle pairs from the tree (not sharing a vertex), and primitive pairs handed to the
  /// test, in the last detect().
  std::size_t last_triangle_pairs() const { return tri_pairs_.size(); }
  std::size_t last_tests() const { return tests_; }
  /// Triangle pairs whose kinetic boxes may meet (their features were examined).
  std::size_t last_kinetic_pairs() const { return kinetic_pairs_; }

 private:
  /// The features one triangle owns: up to three vertices and three edges (ids into edges_).
  struct Owned {
    int vertex[3], edge[3];
    int vertices = 0, edge_count = 0;
  };
  /// A primitive's boxes at the two frames (lo xyz, hi xyz each).
  struct Boxes {
    double b0[6], b1[6];
  };
  void test_pair(int i, int j, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);
  /// Fills near_vf_, near_ee_ with the feature pairs of triangles that share a vertex.
  void list_neighbour_features(int vertex_count);
  /// The test's answer on a query whose boxes may_touch already accepted.
  bool run(const CcdQuery& q) const;

  std::vector<std::array<int, 3>> tris_;
  std::vector<MeshEdge> edges_;
  std::vector<Owned> owned_;
  CcdTest test_;
  TriangleBvh bvh_;
  std::vector<std::array<int, 2>> tri_pairs_;
  std::vector<Boxes> vbox_, ebox_, tbox_;  ///< per vertex, edge, triangle
  std::vector<Vec3> moved_;                 ///< x1 in the frame of the mean displacement
  std::vector<std::array<int, 2>> near_vf_;  ///< (vertex, face) of neighbouring owners
  std::vector<std::array<int, 2>> near_ee_;  ///< (edge, edge) ids of neighbouring owners, in pair order
  std::size_t tests_ = 0, kinetic_pairs_ = 0;
  ContinuousContacts out_;
};

/// One-shot convenience: builds a detector on x0 and detects once.
ContinuousContacts continuous_self_collision(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                                             const std::vector<std::array<int, 3>>& triangles, CcdTest test = nullptr);

/// The pairs of `contacts` for which keep(query) is true, query built from x0, x1 as above:
/// e.g. to confirm core's candidates with an exact referee. Order kept.
ContinuousContacts filter_contacts(const ContinuousContacts& contacts, const std::vector<Vec3>& x0,
                                   const std::vector<Vec3>& x1, const std::vector<std::array<int, 3>>& triangles,
                                   const std::function<bool(const CcdQuery&)>& keep);

}  // namespace tecido
