#pragma once
/// Cloth self-collision detection (seed section 3.1.3): the pairs of triangles of one mesh
/// that intersect, excluding pairs that share a vertex (mesh neighbours always touch).
/// Narrow phase: tecido::tri_tri_intersect (closed triangles, touching counts, exact
/// predicates). Two drivers with identical output:
///  - self_collision_pairs_brute: every pair, O(n^2); kept as the reference for tests;
///  - SelfCollisionDetector: broad phase by a refitted box tree (triangle_bvh.h), then the
///    narrow phase on the candidate pairs; no allocation per frame once warmed up.
/// Positions must be finite.
#include "core/geometry/types.h"

#include "core/cloth/triangle_bvh.h"

#include <array>
#include <cstddef>
#include <vector>

namespace tecido {

/// A pair of triangle ids (i < j).
using TrianglePair = std::array<int, 2>;
/// A triangle-triangle test: true when the closed triangles intersect.
using TriTriTest = bool (*)(const Triangle&, const Triangle&);

/// The default narrow phase: tecido::tri_tri_intersect (core/geometry/tri_tri_intersect.h).
TriTriTest default_tri_tri_test();

/// Every pair (i, j), i < j, of triangles (indices into x) that share no vertex index and
/// intersect according to `test`, sorted lexicographically. Brute force over all pairs.
std::vector<TrianglePair> self_collision_pairs_brute(const std::vector<Vec3>& x,
                                                     const std::vector<std::array<int, 3>>& triangles,
                                                     TriTriTest test = nullptr);

/// Broad phase (box tree built once, refitted per frame) plus narrow phase. detect() returns
/// exactly what self_collision_pairs_brute returns for the same positions and test.
class SelfCollisionDetector {
 public:
  /// Keeps a copy of the triangles; builds the tree from positions x_build (e.g. the rest shape).
  SelfCollisionDetector(const std::vector<std::array<int, 3>>& triangles, const std::vector<Vec3>& x_build,
                        TriTriTest test = nullptr);

  /// The intersecting pairs at positions x, sorted lexicographically (valid until the next call).
  const std::vector<TrianglePair>& detect(const std::vector<Vec3>& x);

  /// Candidate pairs (boxes overlap, no shared vertex) of the last detect(): narrow-phase calls.
  std::size_t last_candidates() const { return candidates_.size(); }
  const std::vector<std::array<int, 3>>& triangles() const { return tris_; }

  /// Threads the narrow phase runs on (>= 1; default 1): the candidates are cut into that many
  /// contiguous shares, one per thread, and the pairs found merged by sorting, so the output
  /// does not depend on it. The tree's traversal stays on the calling thread.
  void set_threads(int threads) { threads_ = threads < 1 ? 1 : threads; }
  /// Shares the last detect() ran (at most the threads asked; one per 4096 candidates).
  int last_parts() const { return parts_; }

 private:
  /// Appends to `out` the candidates [begin, end) that intersect, in candidate order.
  void narrow_phase(const std::vector<Vec3>& x, std::size_t begin, std::size_t end,
                    std::vector<TrianglePair>& out) const;

  std::vector<std::array<int, 3>> tris_;
  TriTriTest test_;
  TriangleBvh bvh_;
  std::vector<TrianglePair> candidates_, pairs_;
  std::vector<std::vector<TrianglePair>> part_pairs_;  ///< per thread, kept across calls
  int threads_ = 1, parts_ = 1;
};

/// One-shot convenience: builds a detector on x and detects once.
std::vector<TrianglePair> self_collision_pairs(const std::vector<Vec3>& x,
                                               const std::vector<std::array<int, 3>>& triangles,
                                               TriTriTest test = nullptr);

}  // namespace tecido
