#include "core/cloth/triangle_bvh.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace tecido {

namespace {
/// The neighbour of a finite float toward -infinity / +infinity (std::nextafter, inlined).
inline float step_down(float f) {
  std::uint32_t b;
  std::memcpy(&b, &f, 4);
  if (f > 0.0f) {
    --b;
  } else if (f < 0.0f) {
    ++b;
  } else {
    b = 0x80000001u;  // -smallest subnormal
  }
  std::memcpy(&f, &b, 4);
  return f;
}
inline float step_up(float f) { return -step_down(-f); }
/// The largest float <= d, and the smallest float >= d (outward rounding of box bounds).
/// A finite double beyond the float range becomes +-infinity, still outward.
inline float float_down(double d) {
  const float f = static_cast<float>(d);
  return static_cast<double>(f) > d ? step_down(f) : f;
}
inline float float_up(double d) {
  const float f = static_cast<float>(d);
  return static_cast<double>(f) < d ? step_up(f) : f;
}
}  // namespace

void TriangleBvh::build(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles) {
  const int n = static_cast<int>(triangles.size());
  slot_tri_.resize(n);
  slot_v_.resize(n);
  slot_box_.resize(n);
  nodes_.clear();
  std::vector<Vec3> centroid(n);
  for (int k = 0; k < n; ++k) {
    slot_tri_[k] = k;
    const auto& t = triangles[k];
    centroid[k] = (x[t[0]] + x[t[1]] + x[t[2]]) / 3.0;
  }
  if (n == 0) return;
  nodes_.reserve(4 * static_cast<std::size_t>(n) / kLeafSize + 1);
  nodes_.push_back(Node{});
  build_node(0, 0, n, centroid);
  for (int k = 0; k < n; ++k) slot_v_[k] = triangles[slot_tri_[k]];
  refit(x);
}

int TriangleBvh::build_node(int node, int begin, int end, const std::vector<Vec3>& centroid) {
  if (end - begin <= kLeafSize) {
    nodes_[node].first = begin;
    nodes_[node].count = end - begin;
    return node;
  }
  Vec3 lo = centroid[slot_tri_[begin]], hi = lo;
  for (int k = begin + 1; k < end; ++k) {
    lo = lo.cwiseMin(centroid[slot_tri_[k]]);
    hi = hi.cwiseMax(centroid[slot_tri_[k]]);
  }
  int axis = 0;
  const Vec3 ext = hi - lo;
  if (ext[1] > ext[axis]) axis = 1;
  if (ext[2] > ext[axis]) axis = 2;
  const int mid = begin + (end - begin) / 2;
  // Strict total order (coordinate, then triangle id): the split does not depend on the
  // standard library's choice among equal keys.
  std::nth_element(slot_tri_.begin() + begin, slot_tri_.begin() + mid, slot_tri_.begin() + end, [&](int a, int b) {
    const double ca = centroid[a][axis], cb = centroid[b][axis];
    return ca < cb || (ca == cb && a < b);
  });
  const int left = static_cast<int>(nodes_.size());
  nodes_.push_back(Node{});
  nodes_.push_back(Node{});
  nodes_[node].first = left;
  nodes_[node].count = 0;
  build_node(left, begin, mid, centroid);
  build_node(left + 1, mid, end, centroid);
  return node;
}

void TriangleBvh::refit(const std::vector<Vec3>& x) {
  const std::size_t n = slot_v_.size();
  for (std::size_t s = 0; s < n; ++s) {
    const Vec3& a = x[slot_v_[s][0]];
    const Vec3& b = x[slot_v_[s][1]];
    const Vec3& c = x[slot_v_[s][2]];
    Box& box = slot_box_[s];
    for (int d = 0; d < 3; ++d) {
      box.lo[d] = float_down(std::min(a[d], std::min(b[d], c[d])));
      box.hi[d] = float_up(std::max(a[d], std::max(b[d], c[d])));
    }
  }
  // Children always have larger indices than their parent: one reverse sweep suffices.
  for (std::size_t k = nodes_.size(); k-- > 0;) {
    Node& node = nodes_[k];
    Box box;
    if (node.count > 0) {
      box = slot_box_[node.first];
      for (int s = node.first + 1; s < node.first + node.count; ++s) {
        for (int d = 0; d < 3; ++d) {
          box.lo[d] = std::min(box.lo[d], slot_box_[s].lo[d]);
          box.hi[d] = std::max(box.hi[d], slot_box_[s].hi[d]);
        }
      }
    } else {
      const Box& l = nodes_[node.first].box;
      const Box& r = nodes_[node.first + 1].box;
      for (int d = 0; d < 3; ++d) {
        box.lo[d] = std::min(l.lo[d], r.lo[d]);
        box.hi[d] = std::max(l.hi[d], r.hi[d]);
      }
    }
    node.box = box;
  }
}

void TriangleBvh::overlapping_pairs(std::vector<std::array<int, 2>>& out) {
  if (nodes_.empty()) return;
  stack_.clear();
  stack_.push_back({0, 0});
  while (!stack_.empty()) {
    const auto [a, b] = stack_.back();
    stack_.pop_back();
    const Node& na = nodes_[a];
    if (a == b) {
      if (na.count > 0) {
        const int end = na.first + na.count;
        for (int s = na.first; s < end; ++s)
          for (int t = s + 1; t < end; ++t)
            if (overlap(slot_box_[s], slot_box_[t]) && !share_vertex(s, t)) emit(s, t, out);
      } else {
        if (overlap(nodes_[na.first].box, nodes_[na.first + 1].box)) stack_.push_back({na.first, na.first + 1});
        stack_.push_back({na.first + 1, na.first + 1});
        stack_.push_back({na.first, na.first});
      }
      continue;
    }
    // Pairs of distinct nodes are pushed only when their boxes overlap.
    const Node& nb = nodes_[b];
    if (na.count > 0 && nb.count > 0) {
      const int ea = na.first + na.count, eb = nb.first + nb.count;
      for (int s = na.first; s < ea; ++s) {
        const Box& bs = slot_box_[s];
        if (!overlap(bs, nb.box)) continue;
        for (int t = nb.first; t < eb; ++t)
          if (overlap(bs, slot_box_[t]) && !share_vertex(s, t)) emit(s, t, out);
      }
      continue;
    }
    // Descend the internal node with the larger box (by the sum of its extents).
    bool split_a = nb.count > 0;
    if (na.count == 0 && nb.count == 0) {
      float ea = 0.0f, eb = 0.0f;
      for (int d = 0; d < 3; ++d) {
        ea += na.box.hi[d] - na.box.lo[d];
        eb += nb.box.hi[d] - nb.box.lo[d];
      }
      split_a = ea >= eb;
    }
    if (split_a) {
      if (overlap(nodes_[na.first + 1].box, nb.box)) stack_.push_back({na.first + 1, b});
      if (overlap(nodes_[na.first].box, nb.box)) stack_.push_back({na.first, b});
    } else {
      if (overlap(na.box, nodes_[nb.first + 1].box)) stack_.push_back({a, nb.first + 1});
      if (overlap(na.box, nodes_[nb.first].box)) stack_.push_back({a, nb.first});
    }
  }
}

}  // namespace tecido
