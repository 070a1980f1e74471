#pragma once
/// Bounding-volume hierarchy of axis-aligned boxes over the triangles of one mesh, built once
/// and refitted every frame: the broad phase of cloth self-collision.
///
/// Method: top-down median split of triangle centroids along the longest axis of their bounds
/// (at build time only), leaves of at most kLeafSize triangles; each frame the boxes are
/// recomputed bottom-up ("refit", van den Bergen 1997, "Efficient collision detection of
/// complex deformable models using AABB trees", J. Graphics Tools 2(4)). A cloth keeps its
/// topology, so a tree built on the rest shape groups mesh patches and stays useful as the
/// cloth deforms. The self-query descends the tree against itself (node with itself: its two
/// children with themselves and with each other), the scheme of Box2D v3's dynamic_tree and
/// of most cloth codes. State lives in flat arrays (nodes, slot boxes, slot vertex ids); a query
/// allocates nothing once its buffers have grown.
#include "core/geometry/types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace tecido {

class TriangleBvh {
 public:
  static constexpr int kLeafSize = 2;

  /// Builds the tree for `triangles` (indices into x) from the positions x. Empty meshes are
  /// allowed. The tree's shape is fixed until the next build; refit() follows the motion.
  void build(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles);

  /// Recomputes every box from positions x (same vertex array the triangles index).
  void refit(const std::vector<Vec3>& x);

  /// Appends to `out` every pair (i, j) of triangle ids, i < j, whose closed boxes overlap
  /// (touching counts) and that share no vertex index; each pair once, in a deterministic
  /// (traversal) order. Uses the boxes of the last build()/refit().
  void overlapping_pairs(std::vector<std::array<int, 2>>& out);

  std::size_t triangle_count() const { return slot_tri_.size(); }
  std::size_t node_count() const { return nodes_.size(); }

 private:
  /// Boxes are stored in single precision, rounded outward (lo down, hi up), so they
  /// contain the double-precision box: the broad phase stays conservative, the exact narrow
  /// phase decides, and the memory traffic of the traversal halves.
  struct Box {
    float lo[3], hi[3];
  };
  struct Node {
    Box box;
    int first = 0;  ///< leaf: first slot; internal: index of the left child (right = first + 1)
    int count = 0;  ///< leaf: number of slots (> 0); internal: 0
  };  // 32 bytes
  int build_node(int node, int begin, int end, const std::vector<Vec3>& centroid);
  static bool overlap(const Box& a, const Box& b) {
    // Non-short-circuit: the outcome is hard to predict, branches cost more than the compares.
    return (a.lo[0] <= b.hi[0]) & (b.lo[0] <= a.hi[0]) & (a.lo[1] <= b.hi[1]) & (b.lo[1] <= a.hi[1]) &
           (a.lo[2] <= b.hi[2]) & (b.lo[2] <= a.hi[2]);
  }
  bool share_vertex(int s, int t) const {
    const auto& a = slot_v_[s];
    const auto& b = slot_v_[t];
    return a[0] == b[0] || a[0] == b[1] || a[0] == b[2] || a[1] == b[0] || a[1] == b[1] || a[1] == b[2] ||
           a[2] == b[0] || a[2] == b[1] || a[2] == b[2];
  }
  void emit(int s, int t, std::vector<std::array<int, 2>>& out) const {
    const int i = slot_tri_[s], j = slot_tri_[t];
    out.push_back(i < j ? std::array<int, 2>{i, j} : std::array<int, 2>{j, i});
  }

  std::vector<Node> nodes_;
  std::vector<int> slot_tri_;               ///< triangle id stored in each slot (leaf order)
  std::vector<std::array<int, 3>> slot_v_;  ///< its vertex ids
  std::vector<Box> slot_box_;               ///< its box
  std::vector<std::array<int, 2>> stack_;   ///< node pairs still to visit
};

}  // namespace tecido
