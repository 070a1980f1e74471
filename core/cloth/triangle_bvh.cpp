#include "core/cloth/triangle_bvh.h"

#include "core/geometry/outward_float.h"
#include "core/platform/parallel_parts.h"
#include "core/simd/dispatch.h"
#include "core/simd/widths.h"

#include <algorithm>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>


namespace tecido {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

/// In a 4 x 4 lane mask (bit 4k + l: lane k of one node, lane l of the other), the bits with
/// k < l: a node paired with itself visits each pair of distinct lanes once.
constexpr unsigned kLaterLanes = 0x08CEu;  // bits 1, 2, 3, 6, 7, 11
static_assert(TriangleBvh::kWidth == 4, "kLaterLanes and the SSE paths assume four lanes");

/// Index of the lowest set bit of a nonzero mask.
inline int lowest_bit(unsigned m) { return __builtin_ctz(m); }

// The lane masks, written once (triangle_bvh_masks.inl) and compiled per width: the narrow
// path is simd2's (SSE2, 4 lanes, part of x86-64), the wide one simd8's (AVX-512F, 16 lanes),
// chosen at run time. The build compiles with -ffp-contract=off (CMakeLists.txt), so the
// AVX-512 copy forms no fused multiply-add in the kinetic test and rounds as the SSE2 one.
#define TECIDO_SIMD_KERNEL "core/cloth/triangle_bvh_masks.inl"
#include "core/simd/for_each_width.inl"

using Narrow = simd2::FloatLanes;

unsigned box_mask(const float* alo, const float* ahi, const float* blo, const float* bhi, bool wide) {
#if TECIDO_SIMD_X86
  if (wide) return simd8::box_mask16<simd8::FloatLanes>(alo, ahi, blo, bhi);
#endif
  (void)wide;
  return simd2::box_mask16<Narrow>(alo, ahi, blo, bhi);
}

unsigned leaf_mask(const float* alo, const float* ahi, const float* blo, const float* bhi, const int* av,
                   const int* bv, bool wide) {
#if TECIDO_SIMD_X86
  if (wide) return simd8::leaf_mask16<simd8::FloatLanes>(alo, ahi, blo, bhi, av, bv);
#endif
  (void)wide;
  return simd2::leaf_mask16<Narrow>(alo, ahi, blo, bhi, av, bv);
}

}  // namespace

bool TriangleBvh::wide_kernel_available() {
  static const bool ok = simd::width_available(8);  // the CPU has AVX-512F and TECIDO_SIMD allows it
  return ok;
}

void TriangleBvh::build(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles) {
  const int n = static_cast<int>(triangles.size());
  tri_count_ = triangles.size();
  nodes_.clear();
  node_box_.clear();
  subtrees_.clear();
  top_nodes_.clear();
  pending_ = Pending::kNone;
  stack_bound_ = 1;
  if (n == 0) return;
  std::vector<Vec3> centroid(n);
  for (int k = 0; k < n; ++k) {
    const auto& t = triangles[k];
    centroid[k] = (x[t[0]] + x[t[1]] + x[t[2]]) / 3.0;
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  nodes_.reserve(static_cast<std::size_t>(n) / 2 + 1);
  nodes_.emplace_back();
  const int depth = build_node(0, 0, n, 0, centroid, order, triangles);
  node_box_.resize(nodes_.size());
  // The refit's order: the nodes above the subtrees children first (larger indices first).
  std::sort(top_nodes_.begin(), top_nodes_.end(), [](int p, int q) { return p > q; });
  // A pop removes one pair and pushes at most kWidth^2; pairs deeper down the tree of node
  // pairs come later, and its paths are at most 2 * depth + 1 long.
  stack_bound_ = static_cast<std::size_t>(kWidth * kWidth) * (2 * static_cast<std::size_t>(depth) + 2) + 1;
  refit(x);
}

int TriangleBvh::build_node(int node, int begin, int end, int level, const std::vector<Vec3>& centroid,
                            std::vector<int>& order, const std::vector<std::array<int, 3>>& triangles) {
  const int count = end - begin;
  if (count <= kWidth) {
    if (level <= kRefitLevel) subtrees_.push_back({node, 0, 0});
    Node& nd = nodes_[node];
    LeafVerts& lv = nd.lv;
    nd.leaf = 1;
    nd.count = count;
    for (int k = 0; k < kWidth; ++k) {
      const bool used = k < count;
      nd.child[k] = used ? order[begin + k] : -1;
      for (int d = 0; d < 3; ++d) {
        lv.v[d][k] = used ? triangles[order[begin + k]][d] : -1 - d;
        nd.lo[d][k] = kInf;
        nd.hi[d][k] = -kInf;
      }
    }
    return 0;
  }
  // Median split of [b, e) along the longest axis of the centroids' bounds, at a multiple of
  // kWidth from b when possible so that leaves come out full. Strict total order (coordinate,
  // then triangle id): the split does not depend on the library's choice among equal keys.
  auto split = [&](int b, int e) {
    Vec3 lo = centroid[order[b]], hi = lo;
    for (int k = b + 1; k < e; ++k) {
      lo = lo.cwiseMin(centroid[order[k]]);
      hi = hi.cwiseMax(centroid[order[k]]);
    }
    int axis = 0;
    const Vec3 ext = hi - lo;
    if (ext[1] > ext[axis]) axis = 1;
    if (ext[2] > ext[axis]) axis = 2;
    const int half = (e - b + 1) / 2;
    const int mid = b + std::min(e - b - 1, (half + kWidth - 1) / kWidth * kWidth);
    std::nth_element(order.begin() + b, order.begin() + mid, order.begin() + e, [&](int p, int q) {
      const double cp = centroid[p][axis], cq = centroid[q][axis];
      return cp < cq || (cp == cq && p < q);
    });
    return mid;
  };
  // Two levels of binary splits give up to four groups; a half that fits in a leaf stays whole.
  int bounds[kWidth + 1];
  int groups = 0;
  const int mid = split(begin, end);
  for (const auto& [b, e] : {std::array<int, 2>{begin, mid}, std::array<int, 2>{mid, end}}) {
    bounds[groups++] = b;
    if (e - b > kWidth) bounds[groups++] = split(b, e);
  }
  bounds[groups] = end;
  const int first = static_cast<int>(nodes_.size());
  for (int g = 0; g < groups; ++g) nodes_.emplace_back();
  {
    Node& nd = nodes_[node];
    nd.leaf = 0;
    nd.count = groups;
    for (int k = 0; k < kWidth; ++k) {
      nd.child[k] = k < groups ? first + k : -1;
      for (int d = 0; d < 3; ++d) {
        nd.lo[d][k] = kInf;
        nd.hi[d][k] = -kInf;
        nd.lv.v[d][k] = -1 - d;
      }
    }
  }
  int depth = 0;
  unsigned leaf_kids = 0;
  for (int g = 0; g < groups; ++g) {
    depth = std::max(depth, build_node(first + g, bounds[g], bounds[g + 1], level + 1, centroid, order, triangles));
    leaf_kids |= static_cast<unsigned>(nodes_[first + g].leaf) << g;
  }
  nodes_[node].leaf_kids = leaf_kids;
  // The nodes below this one are [first, nodes_.size()): children are appended before their
  // own subtrees are built, and every later node descends from them.
  if (level == kRefitLevel) subtrees_.push_back({node, first, static_cast<int>(nodes_.size())});
  if (level < kRefitLevel) top_nodes_.push_back(node);
  return depth + 1;
}

void TriangleBvh::refit(const std::vector<Vec3>& x) {
  if (nodes_.empty()) return;
  const std::size_t nv = x.size();
  vlo_.resize(nv);
  vhi_.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    for (int d = 0; d < 3; ++d) {
      vlo_[v][d] = float_down(x[v][d]);
      vhi_[v][d] = float_up(x[v][d]);
    }
    vlo_[v][3] = vhi_[v][3] = 0.0f;
  }
  pending_ = Pending::kOneFrame;
}

void TriangleBvh::refit(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  if (nodes_.empty()) return;
  const std::size_t nv = x0.size();
  fbounds_.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    FrameBounds& b = fbounds_[v];
    for (int d = 0; d < 3; ++d) {
      b.lo[0][d] = float_down(x0[v][d]);
      b.hi[0][d] = float_up(x0[v][d]);
      b.lo[1][d] = float_down(x1[v][d]);
      b.hi[1][d] = float_up(x1[v][d]);
    }
    b.lo[0][3] = b.hi[0][3] = b.lo[1][3] = b.hi[1][3] = 0.0f;
  }
  pending_ = Pending::kFrames;
}

void TriangleBvh::refit_frames_node(std::size_t k) {
  // Each lane's boxes at both frames, and its swept box (their union: float_down and float_up
  // are monotone, so this is the outward box of both frames).
  Node& nd = nodes_[k];
  Frames& fr = frames_[k];
  for (int lane = 0; lane < kWidth; ++lane) {
    float lo[2][4] = {{kInf, kInf, kInf, kInf}, {kInf, kInf, kInf, kInf}};  // empty lanes: inverted
    float hi[2][4] = {{-kInf, -kInf, -kInf, -kInf}, {-kInf, -kInf, -kInf, -kInf}};
    if (lane < nd.count) {
      for (int f = 0; f < 2; ++f) {
        for (int d = 0; d < 3; ++d) {
          if (nd.leaf) {
            const FrameBounds& a = fbounds_[nd.lv.v[0][lane]];
            const FrameBounds& b = fbounds_[nd.lv.v[1][lane]];
            const FrameBounds& c = fbounds_[nd.lv.v[2][lane]];
            lo[f][d] = std::min(a.lo[f][d], std::min(b.lo[f][d], c.lo[f][d]));
            hi[f][d] = std::max(a.hi[f][d], std::max(b.hi[f][d], c.hi[f][d]));
          } else {
            lo[f][d] = frame_box_[f][nd.child[lane]].lo[d];
            hi[f][d] = frame_box_[f][nd.child[lane]].hi[d];
          }
        }
      }
    }
    for (int d = 0; d < 3; ++d) {
      for (int f = 0; f < 2; ++f) {
        fr.lo[f][d][lane] = lo[f][d];
        fr.hi[f][d][lane] = hi[f][d];
      }
      nd.lo[d][lane] = std::min(lo[0][d], lo[1][d]);
      nd.hi[d][lane] = std::max(hi[0][d], hi[1][d]);
    }
  }
  for (int d = 0; d < 3; ++d) {
    for (int f = 0; f < 2; ++f) {
      Box& box = frame_box_[f][k];
      box.lo[d] = std::min(std::min(fr.lo[f][d][0], fr.lo[f][d][1]), std::min(fr.lo[f][d][2], fr.lo[f][d][3]));
      box.hi[d] = std::max(std::max(fr.hi[f][d][0], fr.hi[f][d][1]), std::max(fr.hi[f][d][2], fr.hi[f][d][3]));
    }
    node_box_[k].lo[d] = std::min(frame_box_[0][k].lo[d], frame_box_[1][k].lo[d]);
    node_box_[k].hi[d] = std::max(frame_box_[0][k].hi[d], frame_box_[1][k].hi[d]);
  }
}

void TriangleBvh::refit_node(std::size_t k) {
  Node& nd = nodes_[k];
  if (nd.leaf) {
    const LeafVerts& lv = nd.lv;
    for (int lane = 0; lane < nd.count; ++lane) {
      const auto& a = vlo_[lv.v[0][lane]];
      const auto& b = vlo_[lv.v[1][lane]];
      const auto& c = vlo_[lv.v[2][lane]];
      const auto& A = vhi_[lv.v[0][lane]];
      const auto& B = vhi_[lv.v[1][lane]];
      const auto& C = vhi_[lv.v[2][lane]];
      for (int d = 0; d < 3; ++d) {
        nd.lo[d][lane] = std::min(a[d], std::min(b[d], c[d]));
        nd.hi[d][lane] = std::max(A[d], std::max(B[d], C[d]));
      }
    }
  } else {
    for (int lane = 0; lane < nd.count; ++lane) {
      const Box& cb = node_box_[nd.child[lane]];
      for (int d = 0; d < 3; ++d) {
        nd.lo[d][lane] = cb.lo[d];
        nd.hi[d][lane] = cb.hi[d];
      }
    }
  }
  Box& box = node_box_[k];
  for (int d = 0; d < 3; ++d) {
    box.lo[d] = std::min(std::min(nd.lo[d][0], nd.lo[d][1]), std::min(nd.lo[d][2], nd.lo[d][3]));
    box.hi[d] = std::max(std::max(nd.hi[d][0], nd.hi[d][1]), std::max(nd.hi[d][2], nd.hi[d][3]));
  }
}

void TriangleBvh::sweep_pending(int parts) {
  if (pending_ == Pending::kNone) return;
  const bool frames = pending_ == Pending::kFrames;
  pending_ = Pending::kNone;
  if (frames) {
    frames_.resize(nodes_.size());
    for (int f = 0; f < 2; ++f) frame_box_[f].resize(nodes_.size());
  }
  const auto refit_one = [this, frames](std::size_t k) { frames ? refit_frames_node(k) : refit_node(k); };
  // Children have larger indices than their parent, and a subtree's nodes below its root are
  // one contiguous range: each subtree is refitted by one reverse sweep of its range, then its
  // root; the subtrees are independent (they share no node), so they can run on any thread.
  // The few nodes above them follow, children first. Every box is computed by the same
  // operations from the same inputs whichever thread does it.
  const auto subtree = [&](const Subtree& s) {
    for (int k = s.end; k-- > s.begin;) refit_one(static_cast<std::size_t>(k));
    refit_one(static_cast<std::size_t>(s.root));
  };
  if (parts <= 1) {
    for (const Subtree& s : subtrees_) subtree(s);
  } else {
    std::atomic<std::size_t> next{0};
    run_parts(parts, [&](int) {
      for (std::size_t t; (t = next.fetch_add(1, std::memory_order_relaxed)) < subtrees_.size();) subtree(subtrees_[t]);
    });
  }
  for (int k : top_nodes_) refit_one(static_cast<std::size_t>(k));
}

unsigned TriangleBvh::lanes_overlapping(const Node& b, const float lo[3], const float hi[3]) {
  return simd2::lanes_overlapping<Narrow>(b.lo[0], b.hi[0], lo, hi);
}

unsigned TriangleBvh::lanes_sharing(const LeafVerts& b, int v0, int v1, int v2) {
  return simd2::lanes_sharing<Narrow>(b.v[0], v0, v1, v2);
}

// The kinetic boxes of two lanes never meet (Method): on each axis, overlap at time t is two
// linear constraints g(t) = (1 - t) g0 + t g1 >= 0 (hi_b - lo_a and hi_a - lo_b, the kinetic
// boxes interpolating the boxes at the frames; ccd/kinetic_boxes.h). In single precision:
//  - v0 = fl(g0): the floats' exact difference rounded once, |v0 - g0| <= 2^-24 |g0| (exact
//    when it underflows); a = fl(v0 + m), m = fl(fl(2^-21 max(|v0|, |v1|)) + FLT_MIN), is at
//    least g0: m >= 2^-21 max (1 - 2^-24) (the product can only lose 2^-150 to underflow, which
//    FLT_MIN more than covers), and fl(v0 + m) >= v0 + m - 2^-24 |v0 + m|, so
//    a >= v0 + 2^-21 |v0| (1 - 2^-24)^2 - 2^-24 |v0| >= g0. Likewise e >= g1. So the line
//    through (0, a) and (1, e) lies above g on [0, 1]: where it is negative, so is g.
//  - a < 0 and e < 0: g < 0 throughout, never overlapping. a < 0 <= e: overlap needs
//    t >= t* = a / (a - e); computed t = t* (1 + d2) / (1 + d1) (a - e adds magnitudes, one
//    rounding; the division one more), so fl(t (1 - 2^-20)) < t* when t is normal, and the
//    final - 2^-100 makes the bound negative when t underflows (absolute error 2^-150).
//    a >= 0 > e: t <= t*, bounded above by fl(t (1 + 2^-20)) + 2^-100 the same way.
//  - disjoint when the largest lower bound exceeds the smallest upper bound (or a constraint
//    is negative at both frames): no time in [0, 1] satisfies all six. A NaN or infinity
//    (boxes near FLT_MAX, empty lanes) makes a comparison false, which never rejects.
// The SSE2 and AVX-512 paths run the same operations lane by lane: the same mask.
unsigned TriangleBvh::kinetic_lanes(const Frames& a, const Frames& b, bool wide) {
#if TECIDO_SIMD_X86
  if (wide) return simd8::kinetic_mask16<simd8::FloatLanes>(&a.lo[0][0][0], &a.hi[0][0][0], &b.lo[0][0][0], &b.hi[0][0][0]);
#endif
  (void)wide;
  return simd2::kinetic_mask16<Narrow>(&a.lo[0][0][0], &a.hi[0][0][0], &b.lo[0][0][0], &b.hi[0][0][0]);
}

unsigned TriangleBvh::kinetic_if_apart(const Frames& a, const Frames& b, unsigned lanes, bool wide) {
  // Lanes whose boxes overlap at a frame are kept by kinetic_lanes too (every constraint is
  // nonnegative at that end: no bound on t from the other), so when no lane of `lanes` is
  // apart at both frames the answer is `lanes` without it. A speed choice of the wide path
  // (two 16-lane compares); the mask is the same either way.
  if (wide) {
    unsigned apart = lanes;
    apart &= ~box_mask(a.lo[0][0], a.hi[0][0], b.lo[0][0], b.hi[0][0], wide);
    apart &= ~box_mask(a.lo[1][0], a.hi[1][0], b.lo[1][0], b.hi[1][0], wide);
    return apart ? (lanes & ~apart) | (apart & kinetic_lanes(a, b, wide)) : lanes;
  }
  return lanes & kinetic_lanes(a, b, wide);
}

template <bool Kinetic>
inline void TriangleBvh::leaf_pairs(int a, int b, bool wide, std::vector<std::array<int, 2>>& out) const {
  const Node& na = nodes_[a];
  const Node& nb = nodes_[b];
  const LeafVerts& la = na.lv;
  const LeafVerts& lb = nb.lv;
  // A 16-bit mask, bit 4k + l for lane k of a and lane l of b, built without branches; then
  // one loop over its (few) set bits. Unused lanes have empty boxes and never overlap.
  unsigned mask = leaf_mask(na.lo[0], na.hi[0], nb.lo[0], nb.hi[0], la.v[0], lb.v[0], wide);
  if (a == b) mask &= kLaterLanes;
  if (Kinetic && mask) mask &= kinetic_lanes(frames_[a], frames_[b], wide);
  for (; mask; mask &= mask - 1) {
    const int bit = lowest_bit(mask);
    const int i = na.child[bit / kWidth], j = nb.child[bit % kWidth];
    // Written in place (not push_back of a temporary, which GCC spills to the stack as two
    // halves and reloads whole: a store-forwarding stall per pair).
    std::array<int, 2>& e = out.emplace_back();
    e[0] = std::min(i, j);
    e[1] = std::max(i, j);
  }
}

void TriangleBvh::overlapping_pairs(std::vector<std::array<int, 2>>& out, int threads) { pairs<false>(out, threads); }

void TriangleBvh::moving_pairs(std::vector<std::array<int, 2>>& out, int threads) { pairs<true>(out, threads); }

namespace {
/// A node pair packed in one 64-bit word (a low, b high): written and read back whole, so the
/// pop right after a push is forwarded from the store buffer.
inline std::uint64_t pack_pair(int a, int b) {
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) | static_cast<std::uint64_t>(static_cast<std::uint32_t>(b)) << 32;
}
inline int pair_first(std::uint64_t e) { return static_cast<int>(static_cast<std::uint32_t>(e)); }
inline int pair_second(std::uint64_t e) { return static_cast<int>(static_cast<std::uint32_t>(e >> 32)); }
}  // namespace

template <bool Kinetic, bool Emit, class Push>
inline void TriangleBvh::visit(int a, int b, bool wide, Push&& push, std::vector<std::array<int, 2>>& out) const {
  // Node pairs still to visit are pairs of internal nodes, or a leaf with an internal node: a
  // pair of leaves is handled where it is found (leaf_kids marks the lanes that are leaves),
  // which spares the stack round trip, a reload of both nodes and an unpredictable branch on
  // their kinds for the most frequent kind of pair.
  const auto prefetch_children = [this](const Node& n) {
    const char* first = reinterpret_cast<const char*>(&nodes_[n.child[0]]);
    for (std::size_t off = 0; off < n.count * sizeof(Node); off += 64) __builtin_prefetch(first + off);
  };
  const auto leaves = [&](int p, int q) {
    if (Emit) leaf_pairs<Kinetic>(p, q, wide, out);
  };
  const Node& na = nodes_[a];
  const Node& nb = nodes_[b];
  if (na.leaf == nb.leaf) {
    // Two internal nodes, or one with itself: every overlapping pair of children, each
    // child with itself for a node with itself. The 4 x 4 mask is built without branches.
    // The children (contiguous records) are about to be read: start fetching them now.
    prefetch_children(na);
    if (a != b) prefetch_children(nb);
    unsigned mask = box_mask(na.lo[0], na.hi[0], nb.lo[0], nb.hi[0], wide);
    if (Kinetic && mask) mask &= kinetic_if_apart(frames_[a], frames_[b], mask, wide);
    if (a == b) {
      mask &= kLaterLanes;
      for (int k = 0; k < na.count; ++k) {
        const int c = na.child[k];
        if ((na.leaf_kids >> k) & 1u) {
          leaves(c, c);
        } else {
          push(c, c);
        }
      }
    }
    for (; mask; mask &= mask - 1) {
      const int bit = lowest_bit(mask);
      const int k = bit / kWidth, l = bit % kWidth;
      if ((na.leaf_kids >> k) & (nb.leaf_kids >> l) & 1u) {
        leaves(na.child[k], nb.child[l]);
      } else {
        push(na.child[k], nb.child[l]);
      }
    }
  } else if (na.leaf) {
    // A leaf against an internal node: descend the internal one.
    prefetch_children(nb);
    for (unsigned m = lanes_overlapping(nb, node_box_[a].lo, node_box_[a].hi); m; m &= m - 1) {
      const int l = lowest_bit(m);
      if ((nb.leaf_kids >> l) & 1u) {
        leaves(a, nb.child[l]);
      } else {
        push(a, nb.child[l]);
      }
    }
  } else {
    prefetch_children(na);
    for (unsigned m = lanes_overlapping(na, node_box_[b].lo, node_box_[b].hi); m; m &= m - 1) {
      const int k = lowest_bit(m);
      if ((na.leaf_kids >> k) & 1u) {
        leaves(na.child[k], b);
      } else {
        push(na.child[k], b);
      }
    }
  }
}

template <bool Kinetic>
void TriangleBvh::plan(int a, int b, int level, bool wide) {
  const Node& na = nodes_[a];
  const Node& nb = nodes_[b];
  if (level >= kTaskLevel || na.leaf || nb.leaf) {
    tasks_.push_back({a, b, 1});
    return;
  }
  // The depth-first traversal from (a, b) writes the leaf pairs (a, b)'s own visit finds,
  // then the whole traversal from each child pair it pushes, the last pushed first (a stack):
  // the tasks are listed in that order.
  std::array<std::uint64_t, kWidth * kWidth + kWidth> kids;
  std::size_t n = 0;
  std::vector<std::array<int, 2>> none;
  visit<Kinetic, false>(a, b, wide, [&](int c, int d) { kids[n++] = pack_pair(c, d); }, none);
  tasks_.push_back({a, b, 0});
  while (n > 0) {
    --n;
    plan<Kinetic>(pair_first(kids[n]), pair_second(kids[n]), level + 1, wide);
  }
}

template <bool Kinetic>
void TriangleBvh::run_task(const Task& task, bool wide, std::uint64_t* stack, std::vector<std::array<int, 2>>& out) const {
  if (!task.whole) {
    visit<Kinetic, true>(task.a, task.b, wide, [](int, int) {}, out);
    return;
  }
  if (nodes_[task.a].leaf && nodes_[task.b].leaf) {  // the root is a leaf
    leaf_pairs<Kinetic>(task.a, task.b, wide, out);
    return;
  }
  std::size_t top = 0;
  stack[top++] = pack_pair(task.a, task.b);
  while (top > 0) {
    const std::uint64_t entry = stack[--top];
    visit<Kinetic, true>(pair_first(entry), pair_second(entry), wide, [&](int c, int d) { stack[top++] = pack_pair(c, d); },
                         out);
  }
}

template <bool Kinetic>
void TriangleBvh::pairs(std::vector<std::array<int, 2>>& out, int threads) {
  last_parts_ = 1;
  if (nodes_.empty()) return;
  const bool wide = use_wide_ && wide_kernel_available();
  // Below a few thousand triangles per thread, starting a thread costs more than it saves.
  const int parts = static_cast<int>(
      std::max<std::size_t>(1, std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), tri_count_ / kTrianglesPerPart)));
  last_parts_ = parts;
  sweep_pending(parts);
  // The traversal is cut into tasks (plan): the same list whatever the number of threads.
  // Each task's pairs are those of one piece of the depth-first traversal, and concatenated in
  // task order they are the traversal's output.
  tasks_.clear();
  plan<Kinetic>(0, 0, 0, wide);
  if (part_state_.size() < static_cast<std::size_t>(parts)) part_state_.resize(static_cast<std::size_t>(parts));
  for (int p = 0; p < parts; ++p) part_state_[static_cast<std::size_t>(p)].stack.resize(stack_bound_);
  if (parts == 1) {
    std::uint64_t* stack = part_state_[0].stack.data();
    for (const Task& task : tasks_) run_task<Kinetic>(task, wide, stack, out);
    return;
  }
  // Tasks are taken in list order by whichever thread is free; each writes its pairs to its
  // thread's buffer and records where. The pairs are then copied out in task order.
  task_out_.resize(tasks_.size());
  std::atomic<std::size_t> next{0};
  run_parts(parts, [&](int part) {
    PartState& ps = part_state_[static_cast<std::size_t>(part)];
    ps.out.clear();
    for (std::size_t t; (t = next.fetch_add(1, std::memory_order_relaxed)) < tasks_.size();) {
      const std::size_t begin = ps.out.size();
      run_task<Kinetic>(tasks_[t], wide, ps.stack.data(), ps.out);
      task_out_[t] = {part, begin, ps.out.size()};
    }
  });
  for (const TaskOutput& r : task_out_) {
    const auto& src = part_state_[static_cast<std::size_t>(r.part)].out;
    out.insert(out.end(), src.begin() + static_cast<std::ptrdiff_t>(r.begin), src.begin() + static_cast<std::ptrdiff_t>(r.end));
  }
}

}  // namespace tecido
