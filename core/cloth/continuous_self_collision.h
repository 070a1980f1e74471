#pragma once
/// Continuous self-collision of one triangle mesh moving linearly between two frames: every
/// vertex-face pair (the vertex not a corner of the face) and every edge-edge pair (edges
/// sharing no vertex) that may touch at some time of the motion, according to a continuous
/// collision test (default: core's, core/geometry/ccd/ccd.h: no false negatives, near misses within
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
///    from the triangle box tree (triangle_bvh.h) refitted on both frames (in a frame moving
///    with the mesh's mean displacement, which changes no contact): pairs whose swept boxes
///    overlap and whose kinetic boxes may meet (a certified single-precision test; each
///    triangle's boxes contain its owned features' at every time). Feature pairs whose swept
///    boxes, rounded outward to floats, overlap are queued (disjoint ones ccd's stage 2 would
///    reject), and the first stages of core's test run on them in batches, several per SIMD
///    register (ccd/batch/stages.h: swept and kinetic boxes, the coplanarity cubic, then the
///    root of ccd's time search; bit for bit ccd's own decisions on the same numbers); the test
///    itself runs on the pairs they leave open, from the stage after the boxes.
/// Output: vertex_face as (v, f), 0-based vertex and face indices, sorted; edge_edge as
/// ((a, b), (c, d)) with a < b, c < d and (a, b) < (c, d), sorted lexicographically.
/// Positions must be finite; both frames have the same size; no triangle repeats an index.
#include "core/geometry/ccd/query.h"

#include "core/cloth/triangle_bvh.h"

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
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
  /// Triangle pairs whose kinetic boxes may meet (their features were examined): the tree's
  /// pairs, whose kinetic boxes it already tests.
  std::size_t last_kinetic_pairs() const { return tri_pairs_.size(); }

 /// The widths of core's batched first stages (core/geometry/ccd/batch/stages.h): 0 the
  /// widest this CPU runs (default), or 2, 4, 8 when available. The output does not depend on
  /// it; tests compare.
  void set_simd_width(int width) { width_ = width; }

  /// Threads detect() runs the feature pairs on (>= 1; default 1): the tree pairs and the
  /// neighbour pairs are cut into that many contiguous shares, one per thread, and the pairs
  /// found are merged by sorting, so the output and last_tests() do not depend on it. The tree's
  /// traversal stays on the calling thread.
  void set_threads(int threads) { threads_ = threads < 1 ? 1 : threads; }
  /// Shares the last detect() ran (at most the threads asked; fewer on small work, where
  /// starting a thread costs more than its share: one per 4096 tree and neighbour pairs).
  int last_parts() const { return parts_; }

 private:
  /// A triangle and the features it owns (the first triangle that has a vertex or an edge owns
  /// it): bit k of owns_vertex for corner v[k], bit k of owns_edge for edge k, (v[k], v[k+1 mod 3]),
  /// whose id is edge[k].
  struct TriangleRecord {
    int v[3];
    int edge[3];
    unsigned owns_vertex = 0, owns_edge = 0;
  };
  /// A vertex's positions at both frames, in one cache line.
  struct alignas(64) VertexFrames {
    double x0[3], x1[3];
  };
  /// A swept box (over both frames) rounded outward to floats (core/geometry/outward_float.h):
  /// it contains the double-precision swept box, so boxes disjoint in floats are disjoint in
  /// doubles, and ccd's stage 2 rejects their pair. The fourth lane is padding (0).
  struct alignas(16) FloatBox {
    float lo[4], hi[4];
  };
  static FloatBox merged(const FloatBox& a, const FloatBox& b);
  /// Closed boxes overlap (touching counts).
  static bool overlap(const FloatBox& a, const FloatBox& b);
  /// Primitive pairs of one kind waiting for the batched first stages: the query's points
  /// (ccd/query.h order) and the pair's output key, `count` of them.
  struct Pending {
    std::array<std::array<int, 4>, 256> points;
    std::array<std::uint64_t, 256> keys;
    int count = 0;
  };
  /// One worker's state (a thread's, when detect() runs on several): its queues, the first
  /// stages' verdicts, its count of tests and the keys of the pairs it found.
  struct Worker {
    Pending pending[2];  ///< [0] vertex-face, [1] edge-edge
    std::vector<std::uint8_t> verdict;
    std::size_t tests = 0;
    std::vector<std::uint64_t> vf_keys;  ///< pairs found: v << 32 | f
    std::vector<std::uint64_t> ee_keys;  ///< pairs found: edge id << 32 | edge id, ids ascending
  };
  /// Share `part` of `parts` of the work (tree pairs and neighbour pairs), flushed.
  /// Takes chunks from `next` until all `chunks` are taken, then flushes the worker's queues.
  void work(Worker& w, std::atomic<int>& next, int chunks, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);
  /// Chunk `part` of `parts`: a contiguous share of the tree pairs and of each neighbour list.
  void work_chunk(Worker& w, int part, int parts, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);
  /// The feature pairs of tree pair (i, j) whose swept boxes overlap, queued.
  void test_pair(Worker& w, int i, int j, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);
  /// Queues one primitive pair when `keep`; runs the queue when it is full.
  void push(Worker& w, CcdKind kind, const std::array<int, 4>& points, std::uint64_t key, bool keep,
            const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);
  /// Runs both queues.
  void flush(Worker& w, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);
  /// The first stages on n queued pairs, then the test on those they leave open; keys of
  /// pairs the test accepts go to the worker's vf_keys / ee_keys.
  void sift(Worker& w, CcdKind kind, const std::array<int, 4>* points, const std::uint64_t* keys, int n,
            const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);
  /// Queues the listed pairs [begin, end) of features of neighbouring owners (kind 0
  /// vertex-face, 1 edge-edge) whose swept boxes overlap.
  void sift_neighbours(Worker& w, int kind, std::size_t begin, std::size_t end, const std::vector<Vec3>& x0,
                       const std::vector<Vec3>& x1);
  /// work() on threads_ workers (the calling thread one of them); merges their keys and counts.
  void run_workers(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);
  /// Fills the near_ lists with the feature pairs of triangles that share a vertex.
  void list_neighbour_features(int vertex_count);
  /// Appends the feature pairs of neighbouring triangles i <= j (i == j: a corner repeated).
  void list_feature_pairs(int i, int j);
  /// The test's answer on a query whose box stages were passed.
  bool run(const CcdQuery& q) const;
  /// Sorts the keys of the pairs found and writes them out as pairs into out_.
  void emit_sorted();

  std::vector<std::array<int, 3>> tris_;
  std::vector<MeshEdge> edges_;
  std::vector<TriangleRecord> records_;
  CcdTest test_;
  TriangleBvh bvh_;
  std::vector<std::array<int, 2>> tri_pairs_;
  std::vector<VertexFrames> frames_;  ///< per vertex, this detect()'s positions
  std::vector<FloatBox> boxes_;       ///< per vertex, its swept box rounded outward
  std::vector<Vec3> moved_;           ///< x1 in the frame of the mean displacement
  /// Pairs of features of neighbouring owners, as query points and keys (vertex-face: v << 32
  /// | f; edge-edge: ids ascending), in pair order.
  std::vector<std::array<int, 4>> near_vf_points_, near_ee_points_;
  std::vector<std::uint64_t> near_vf_keys_, near_ee_keys_;
  std::vector<Worker> workers_;        ///< one per thread, kept across calls
  int width_ = 0;
  int threads_ = 1, parts_ = 1;
  std::size_t tests_ = 0;
  std::vector<std::uint64_t> vf_keys_, ee_keys_;  ///< all workers' keys, merged
  ContinuousContacts out_;
};

/// One-shot convenience: builds a detector on x0 and detects once.
ContinuousContacts continuous_self_collision(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                                             const std::vector<std::array<int, 3>>& triangles, CcdTest test = nullptr);

/// The pairs of `contacts` for which keep(query) is true, query built from x0, x1 as above:
/// e.g. to confirm core's candidates with an exact referee. Order kept. With threads > 1 the
/// pairs are cut into that many contiguous shares, one per thread (keep must be safe to call
/// concurrently); the output is the same.
ContinuousContacts filter_contacts(const ContinuousContacts& contacts, const std::vector<Vec3>& x0,
                                   const std::vector<Vec3>& x1, const std::vector<std::array<int, 3>>& triangles,
                                   const std::function<bool(const CcdQuery&)>& keep, int threads = 1);

}  // namespace tecido
