#pragma once
/// Bounding-volume hierarchy of axis-aligned boxes over the triangles of one mesh, built once
/// and refitted every frame: the broad phase of cloth self-collision.
///
/// Method: a 4-ary tree (each node holds the boxes of its up to four children side by side,
/// "structure of arrays", so one box is tested against all four with a handful of vector
/// compares; Wald et al. 2008, "Getting rid of packets", and Embree's BVH4). It is built top
/// down by two median splits of triangle centroids along the longest axis of their bounds (at
/// build time only); a leaf holds up to four triangles. Each frame the boxes are recomputed
/// bottom-up ("refit", van den Bergen 1997, "Efficient collision detection of complex
/// deformable models using AABB trees", J. Graphics Tools 2(4)). A cloth keeps its topology, so
/// a tree built on the rest shape groups mesh patches and stays useful as the cloth deforms.
/// The self-query descends the tree against itself (a node with itself: each child with itself
/// and every two overlapping children with each other; two distinct nodes: every overlapping
/// pair of their children), as in Box2D v3's dynamic_tree and most cloth codes, branch-free
/// where the outcome is a coin toss. State lives in flat arrays; a one-thread query allocates
/// nothing once its buffers have grown.
///
/// Threads: that depth-first traversal writes a node pair's own leaf pairs, then the traversal
/// from each child pair it pushed, the last pushed first; so a query lists, on the calling
/// thread, the pieces of it down to depth kTaskLevel ("tasks", the same list at any thread
/// count), threads run the tasks into their own buffers, and the buffers are copied out in task
/// order: the one-thread output, pair for pair. refit() leaves the node boxes to the next query,
/// which recomputes the independent subtrees below depth kRefitLevel on its threads, then the
/// nodes above.
///
/// Cost model (256x256 folded cloth: ~54k nodes, ~6 MB, beyond L2): the query is bound by the
/// first touch of each node and by the 4 x 4 lane masks. So a pair of leaves is handled where
/// it is found (never pushed), each node's children, stored contiguously, are prefetched as
/// soon as the node is popped, and on AVX-512 CPUs (run-time check) each 4 x 4 mask is one
/// 16-lane pass instead of four 4-lane ones; the masks, hence the output, are the same.
///
/// Boxes are stored in single precision, rounded outward (each vertex's coordinates widened by
/// at least one float ulp), so they contain the double-precision boxes: the broad phase stays
/// conservative, the exact narrow phase decides, and the memory traffic halves.
#include "core/geometry/types.h"

#include <array>
#include <cstdint>
#include <vector>

namespace tecido {

class TriangleBvh {
 public:
  static constexpr int kWidth = 4;  ///< children per node, triangles per leaf

  /// Builds the tree for `triangles` (indices into x) from the positions x. Empty meshes are
  /// allowed. The tree's shape is fixed until the next build; refit() follows the motion.
  void build(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles);

  /// Recomputes every box from positions x (same vertex array the triangles index; finite).
  /// The vertices' bounds are taken now; the nodes' boxes are brought up to date by the next
  /// query, on that query's threads (the boxes are the same either way).
  void refit(const std::vector<Vec3>& x);

  /// Recomputes every box as the swept box of linear motion from x0 to x1: the union of the
  /// boxes at both frames, which contains the triangle at every time in between (continuous
  /// collision, core/cloth/continuous_self_collision.h). Finite positions, same sizes. Keeps
  /// the boxes at each frame as well, for moving_pairs().
  void refit(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1);

  /// Appends to `out` every pair (i, j) of triangle ids, i < j, whose closed boxes overlap
  /// (touching counts) and that share no vertex index; each pair once, in a deterministic
  /// (traversal) order. Uses the boxes of the last build()/refit(). Runs on up to `threads`
  /// threads (the calling one included; one per kTrianglesPerPart triangles at most): the
  /// same pairs in the same order at any thread count (Threads, above).
  void overlapping_pairs(std::vector<std::array<int, 2>>& out, int threads = 1);

  /// After the two-frame refit: the pairs of overlapping_pairs() less those whose kinetic
  /// boxes never meet (the boxes at t = 0 and t = 1 interpolated in time, as in
  /// core/geometry/ccd/kinetic_boxes.h; each triangle lies in its kinetic box at every time,
  /// so such a pair cannot touch), decided by a certified test in single precision
  /// (kinetic_lanes in triangle_bvh.cpp) on the lanes of leaf pairs and of internal node
  /// pairs (a node's boxes at each frame contain its triangles'). In the same order, and the
  /// same at any thread count.
  void moving_pairs(std::vector<std::array<int, 2>>& out, int threads = 1);

  /// Triangles per thread below which a query uses fewer threads than asked.
  static constexpr std::size_t kTrianglesPerPart = 2048;
  /// Threads the last query ran on.
  int last_parts() const { return last_parts_; }

  /// The leaf and node-pair masks use one 16-lane AVX-512 pass when the CPU has AVX-512F
  /// (checked at run time), SSE2 otherwise; the output does not depend on the path. Tests can
  /// switch the wide path off to compare both.
  static bool wide_kernel_available();
  void set_use_wide_kernel(bool on) { use_wide_ = on; }

  std::size_t triangle_count() const { return tri_count_; }
  std::size_t node_count() const { return nodes_.size(); }

 private:
  /// The refit's independent subtrees are rooted at this depth (root: 0), up to 4^3 = 64.
  static constexpr int kRefitLevel = 3;
  /// The traversal's tasks: node pairs at this depth (or above, where a leaf is met).
  static constexpr int kTaskLevel = 4;
  /// The vertex ids of a leaf's triangles, lane by lane (unused lanes: -1, -2, -3).
  struct LeafVerts {
    int v[3][kWidth];
  };
  /// A node: the boxes of its children (lanes), lane k empty (lo = +inf, hi = -inf) when k >= count.
  /// Leaves carry their triangles' vertex ids in the same record, so that a pair of leaves
  /// reads two contiguous, cache-line-aligned records (three lines each) and nothing else.
  struct alignas(64) Node {
    float lo[3][kWidth], hi[3][kWidth];
    LeafVerts lv;       ///< leaf: vertex ids of the lanes' triangles; internal: -1, -2, -3
    int child[kWidth];  ///< internal: child node indices; leaf: triangle ids
    int count = 0;      ///< lanes in use, 1..kWidth
    int leaf = 0;       ///< 1 when the lanes are triangles
    unsigned leaf_kids = 0;  ///< internal: bit k set when child k is a leaf
  };
  /// A node's own box (the union of its lanes), kept for pairs of a leaf with an internal node.
  struct Box {
    float lo[3], hi[3];
  };
  /// The boxes of a node's lanes at each frame of the two-frame refit: lo[frame][axis][lane].
  struct alignas(64) Frames {
    float lo[2][3][kWidth], hi[2][3][kWidth];
  };

  /// A subtree refitted as one job: its root, and the nodes below it, [begin, end).
  struct Subtree {
    int root, begin, end;
  };
  /// A piece of the traversal: the whole depth-first traversal from node pair (a, b)
  /// (whole = 1), or only the leaf pairs (a, b)'s own visit finds (whole = 0).
  struct Task {
    int a, b, whole;
  };
  /// Where a task's pairs went: part's buffer, [begin, end).
  struct TaskOutput {
    int part;
    std::size_t begin, end;
  };
  /// A thread's traversal stack and pairs, kept across queries. A cache line each: a thread
  /// moves its vectors' ends at every pair, which must not evict another thread's line.
  struct alignas(64) PartState {
    std::vector<std::uint64_t> stack;
    std::vector<std::array<int, 2>> out;
  };
  /// The node sweep refit() left to the next query.
  enum class Pending { kNone, kOneFrame, kFrames };

  int build_node(int node, int begin, int end, int level, const std::vector<Vec3>& centroid, std::vector<int>& order,
                 const std::vector<std::array<int, 3>>& triangles);
  /// The traversal of overlapping_pairs (Kinetic false) and moving_pairs (true).
  template <bool Kinetic>
  void pairs(std::vector<std::array<int, 2>>& out, int threads);
  /// One step of the traversal at node pair (a, b): appends the pairs of the leaf pairs it
  /// finds (when Emit) and calls push(c, d) for each node pair to descend, in traversal order.
  template <bool Kinetic, bool Emit, class Push>
  void visit(int a, int b, bool wide, Push&& push, std::vector<std::array<int, 2>>& out) const;
  /// Appends to tasks_ the tasks of the traversal from (a, b) at depth `level`, in order.
  template <bool Kinetic>
  void plan(int a, int b, int level, bool wide);
  /// Appends the pairs of one task; stack: room for stack_bound_ node pairs.
  template <bool Kinetic>
  void run_task(const Task& task, bool wide, std::uint64_t* stack, std::vector<std::array<int, 2>>& out) const;
  /// Appends the triangle pairs of leaves a and b (a == b: the leaf with itself).
  template <bool Kinetic>
  void leaf_pairs(int a, int b, bool wide, std::vector<std::array<int, 2>>& out) const;
  /// Bit 4k + l set when the kinetic boxes of lane k of a and lane l of b may meet.
  static unsigned kinetic_lanes(const Frames& a, const Frames& b, bool wide);
  /// lanes & kinetic_lanes(a, b), skipping the kinetic test when no lane is apart at both
  /// frames (internal node pairs, where most overlap at a frame).
  static unsigned kinetic_if_apart(const Frames& a, const Frames& b, unsigned lanes, bool wide);
  /// Bit k set when lane k of node b overlaps box (lo, hi).
  static unsigned lanes_overlapping(const Node& b, const float lo[3], const float hi[3]);
  /// Bit k set when triangle (v0, v1, v2) shares a vertex with lane k's triangle of leaf b.
  static unsigned lanes_sharing(const LeafVerts& b, int v0, int v1, int v2);
  /// Node k's boxes from its children's (or its triangles' per-vertex bounds vlo_, vhi_).
  void refit_node(std::size_t k);
  /// Node k's lanes at both frames (frames_) and swept (the node's own lo, hi), from its
  /// children's or the per-vertex bounds of each frame, fbounds_.
  void refit_frames_node(std::size_t k);
  /// The node sweep pending_ asks for, on up to `parts` threads.
  void sweep_pending(int parts);

  std::size_t tri_count_ = 0;
  std::vector<Node> nodes_;          ///< nodes_[0] is the root; children after their parent
  std::vector<Box> node_box_;        ///< each node's own box
  std::vector<std::array<float, 4>> vlo_, vhi_;  ///< per-vertex outward float bounds
  /// A vertex's outward float bounds at each frame (two-frame refit): lo[frame][axis], pad 0.
  struct alignas(32) FrameBounds {
    float lo[2][4], hi[2][4];
  };
  std::vector<FrameBounds> fbounds_;
  std::vector<Frames> frames_;                     ///< per node (two-frame refit)
  std::vector<Box> frame_box_[2];                  ///< each node's own box per frame
  std::vector<Subtree> subtrees_;     ///< the refit's jobs
  std::vector<int> top_nodes_;        ///< the nodes above subtrees_, children first
  Pending pending_ = Pending::kNone;
  std::vector<Task> tasks_;            ///< the last query's tasks, in traversal order
  std::vector<TaskOutput> task_out_;   ///< per task (queries on several threads)
  std::vector<PartState> part_state_;  ///< per thread; the stacks hold node pairs (a | b << 32)
  int last_parts_ = 1;
  /// Bound on the stack's size: a pop pushes at most kWidth^2 pairs minus the one it removed,
  /// and a path down the tree of node pairs is at most 2 * depth + 1 long.
  std::size_t stack_bound_ = 1;
  bool use_wide_ = true;
};

}  // namespace tecido
