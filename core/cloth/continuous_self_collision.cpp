#include "core/cloth/continuous_self_collision.h"

#include "core/cloth/mesh_topology.h"
#include "core/geometry/ccd.h"
#include "core/geometry/ccd_batch_stages.h"
#include "core/geometry/ccd_pipeline.h"

#include <algorithm>
#include <cstdint>

namespace tecido {

namespace {

CcdAnswer default_test(const CcdQuery& q) { return ccd(q); }

bool has_vertex(const std::array<int, 3>& t, int v) { return t[0] == v || t[1] == v || t[2] == v; }

bool share_vertex(const MeshEdge& e, const MeshEdge& f) { return e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1]; }

/// A pair of nonnegative ids packed so that integer order is the pairs' lexicographic order.
std::uint64_t pair_key(int a, int b) { return static_cast<std::uint64_t>(a) << 32 | static_cast<std::uint32_t>(b); }

void sort_contacts(ContinuousContacts& c) {
  std::sort(c.vertex_face.begin(), c.vertex_face.end());
  std::sort(c.edge_edge.begin(), c.edge_edge.end());
}

/// The unique edges of the mesh, (a, b) with a < b, sorted.
std::vector<MeshEdge> mesh_edges(const std::vector<std::array<int, 3>>& triangles) {
  int nv = 0;
  for (const auto& t : triangles)
    for (int v : t) nv = std::max(nv, v + 1);
  return build_mesh_topology(nv, triangles).edges;
}

/// Extends box b (lo xyz, hi xyz) by point p.
void extend(double b[6], const Vec3& p) {
  for (int c = 0; c < 3; ++c) {
    b[c] = std::min(b[c], p[c]);
    b[c + 3] = std::max(b[c + 3], p[c]);
  }
}

void point_box(double b[6], const Vec3& p) {
  for (int c = 0; c < 3; ++c) b[c] = b[c + 3] = p[c];
}

/// The box of two boxes (lo xyz, hi xyz).
template <class S>
S merged(const S& a, const S& b) {
  S m;
  for (int c = 0; c < 3; ++c) {
    m.b[c] = std::min(a.b[c], b.b[c]);
    m.b[c + 3] = std::max(a.b[c + 3], b.b[c + 3]);
  }
  return m;
}

/// Pairs queued before the batched first stages run on them.
constexpr int kChunk = 256;

CcdQuery query_of(CcdKind kind, const std::array<int, 4>& points, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  CcdQuery q;
  q.kind = kind;
  for (int k = 0; k < 4; ++k) {
    q.x0[k] = x0[points[k]];
    q.x1[k] = x1[points[k]];
  }
  return q;
}

/// Swept boxes (lo xyz, hi xyz over both frames) overlap: exact comparisons, as
/// ccd_pipeline.cpp's stage 2 (its boxes are the same minima and maxima of the same points).
bool swept_overlap(const double a[6], const double b[6]) {
  return !(a[3] < b[0] || b[3] < a[0] || a[4] < b[1] || b[4] < a[1] || a[5] < b[2] || b[5] < a[2]);
}

}  // namespace

CcdQuery vertex_face_query(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, int v, const std::array<int, 3>& tri) {
  CcdQuery q;
  q.kind = CcdKind::VertexFace;
  q.x0 = {x0[v], x0[tri[0]], x0[tri[1]], x0[tri[2]]};
  q.x1 = {x1[v], x1[tri[0]], x1[tri[1]], x1[tri[2]]};
  return q;
}

CcdQuery edge_edge_query(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, const MeshEdge& e, const MeshEdge& f) {
  CcdQuery q;
  q.kind = CcdKind::EdgeEdge;
  q.x0 = {x0[e[0]], x0[e[1]], x0[f[0]], x0[f[1]]};
  q.x1 = {x1[e[0]], x1[e[1]], x1[f[0]], x1[f[1]]};
  return q;
}

ContinuousContacts continuous_self_collision_brute(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                                                   const std::vector<std::array<int, 3>>& triangles, CcdTest test) {
  if (!test) test = &default_test;
  ContinuousContacts out;
  std::vector<char> used(x0.size(), 0);
  for (const auto& t : triangles)
    for (int v : t) used[v] = 1;
  for (int v = 0; v < static_cast<int>(x0.size()); ++v) {
    if (!used[v]) continue;
    for (int f = 0; f < static_cast<int>(triangles.size()); ++f)
      if (!has_vertex(triangles[f], v) && test(vertex_face_query(x0, x1, v, triangles[f])).hit) out.vertex_face.push_back({v, f});
  }
  const std::vector<MeshEdge> edges = mesh_edges(triangles);
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j)
      if (!share_vertex(edges[i], edges[j]) && test(edge_edge_query(x0, x1, edges[i], edges[j])).hit)
        out.edge_edge.push_back({edges[i], edges[j]});  // edges are sorted: already in order
  sort_contacts(out);
  return out;
}

ContinuousSelfCollisionDetector::ContinuousSelfCollisionDetector(const std::vector<std::array<int, 3>>& triangles,
                                                                 const std::vector<Vec3>& x_build, CcdTest test)
    : tris_(triangles), test_(test ? test : &default_test) {
  int nv = 0;
  for (const auto& t : tris_)
    for (int v : t) nv = std::max(nv, v + 1);
  const MeshTopology topo = build_mesh_topology(nv, tris_);
  edges_ = topo.edges;
  // Owners: the first triangle that has the vertex or edge.
  owned_.assign(tris_.size(), Owned{});
  std::vector<char> vertex_taken(nv, 0), edge_taken(edges_.size(), 0);
  for (std::size_t t = 0; t < tris_.size(); ++t) {
    Owned& o = owned_[t];
    for (int k = 0; k < 3; ++k) {
      const int v = tris_[t][k], e = topo.tri_edges[t][k];
      if (!vertex_taken[v]) {
        vertex_taken[v] = 1;
        o.vertex[o.vertices++] = v;
      }
      if (!edge_taken[e]) {
        edge_taken[e] = 1;
        o.edge[o.edge_count++] = e;
      }
    }
  }
  list_neighbour_features(nv);
  bvh_.build(x_build, tris_);
}

void ContinuousSelfCollisionDetector::list_neighbour_features(int vertex_count) {
  // Triangles around each vertex (CSR), then every pair of distinct triangles sharing one.
  std::vector<int> start(vertex_count + 1, 0), around(3 * tris_.size());
  for (const auto& t : tris_)
    for (int v : t) ++start[v + 1];
  for (int v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < tris_.size(); ++t)
    for (int v : tris_[t]) around[fill[v]++] = static_cast<int>(t);
  std::vector<std::array<int, 2>> neighbours;
  for (int v = 0; v < vertex_count; ++v)
    for (int a = start[v]; a < start[v + 1]; ++a)
      for (int b = a + 1; b < start[v + 1]; ++b) neighbours.push_back({around[a], around[b]});
  std::sort(neighbours.begin(), neighbours.end());
  neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  // Their feature pairs, chosen exactly as test_pair chooses them (each primitive pair comes
  // from the triangle pair of its owners), without the boxes.
  for (const auto& [i, j] : neighbours) {
    for (int side = 0; side < 2; ++side) {
      const Owned& o = owned_[side == 0 ? i : j];
      const int f = side == 0 ? j : i;
      const std::array<int, 3>& face = tris_[f];
      for (int k = 0; k < o.vertices; ++k) {
        if (has_vertex(face, o.vertex[k])) continue;
        near_vf_points_.push_back({o.vertex[k], face[0], face[1], face[2]});
        near_vf_keys_.push_back(pair_key(o.vertex[k], f));
      }
    }
    for (int a = 0; a < owned_[i].edge_count; ++a) {
      for (int b = 0; b < owned_[j].edge_count; ++b) {
        const int ea = owned_[i].edge[a], eb = owned_[j].edge[b];
        if (share_vertex(edges_[ea], edges_[eb])) continue;
        const MeshEdge& e = edges_[std::min(ea, eb)];
        const MeshEdge& g = edges_[std::max(ea, eb)];
        near_ee_points_.push_back({e[0], e[1], g[0], g[1]});
        near_ee_keys_.push_back(pair_key(std::min(ea, eb), std::max(ea, eb)));
      }
    }
  }
}

bool ContinuousSelfCollisionDetector::run(const CcdQuery& q) const {
  // Core's test: its box stages (and, when they certify, the cubic) were already run here on
  // the same numbers, so go on from the next stage (the same answer).
  return test_ == &default_test ? ccd_after_boxes(q).hit : test_(q).hit;
}

void ContinuousSelfCollisionDetector::sift(CcdKind kind, const std::array<int, 4>* points, const std::uint64_t* keys,
                                          int n, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "positions are read as packed doubles");
  const double* p0 = reinterpret_cast<const double*>(x0.data());
  const double* p1 = reinterpret_cast<const double*>(x1.data());
  // The cubic verdict is core's test's own stage: a custom test gets the box stages only.
  const bool cubic = test_ == &default_test;
  std::vector<std::uint64_t>& found = kind == CcdKind::VertexFace ? vf_keys_ : ee_keys_;
  verdict_.resize(kChunk);
  for (int first = 0; first < n; first += kChunk) {
    const int m = std::min(kChunk, n - first);
    ccd_batch_first_stages(kind, p0, p1, points + first, m, cubic, verdict_.data(), width_);
    for (int k = 0; k < m; ++k) {
      const std::uint8_t v = verdict_[k];
      if (v & kCcdBoxesDisjoint) continue;
      ++tests_;  // the pair passed the box stages: handed to the test
      if (v & kCcdCubicMiss) continue;
      if (run(query_of(kind, points[first + k], x0, x1))) found.push_back(keys[first + k]);
    }
  }
}

void ContinuousSelfCollisionDetector::push(CcdKind kind, const std::array<int, 4>& points, std::uint64_t key,
                                          const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  Pending& p = pending_[kind == CcdKind::VertexFace ? 0 : 1];
  p.points.push_back(points);
  p.keys.push_back(key);
  if (p.points.size() < static_cast<std::size_t>(kChunk)) return;
  sift(kind, p.points.data(), p.keys.data(), kChunk, x0, x1);
  p.points.clear();
  p.keys.clear();
}

void ContinuousSelfCollisionDetector::flush(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  for (int kind = 0; kind < 2; ++kind) {
    Pending& p = pending_[kind];
    sift(kind == 0 ? CcdKind::VertexFace : CcdKind::EdgeEdge, p.points.data(), p.keys.data(),
         static_cast<int>(p.points.size()), x0, x1);
    p.points.clear();
    p.keys.clear();
  }
}

void ContinuousSelfCollisionDetector::test_pair(int i, int j, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  const Owned& oi = owned_[i];
  const Owned& oj = owned_[j];
  // Vertices of one triangle against the other face.
  for (int side = 0; side < 2; ++side) {
    const Owned& o = side == 0 ? oi : oj;
    const int f = side == 0 ? j : i;
    const std::array<int, 3>& face = tris_[f];
    for (int k = 0; k < o.vertices; ++k) {
      const int v = o.vertex[k];
      if (!has_vertex(face, v) && swept_overlap(vsw_[v].b, tsw_[f].b))
        push(CcdKind::VertexFace, {v, face[0], face[1], face[2]}, pair_key(v, f), x0, x1);
    }
  }
  // Edges of one against edges of the other. An edge whose swept box misses the other
  // triangle's misses those of its edges (they lie inside): ccd's stage 2 rejects them all.
  for (int a = 0; a < oi.edge_count; ++a) {
    const int ea = oi.edge[a];
    if (!swept_overlap(esw_[ea].b, tsw_[j].b)) continue;
    for (int b = 0; b < oj.edge_count; ++b) {
      const int eb = oj.edge[b];
      if (share_vertex(edges_[ea], edges_[eb]) || !swept_overlap(esw_[ea].b, esw_[eb].b)) continue;
      // The query in the pair's own order (as the brute force builds it): same answer. Edge
      // ids are numbered in the edges' sorted order, so the smaller id is the first edge.
      const int lo = std::min(ea, eb), hi = std::max(ea, eb);
      push(CcdKind::EdgeEdge, {edges_[lo][0], edges_[lo][1], edges_[hi][0], edges_[hi][1]}, pair_key(lo, hi), x0, x1);
    }
  }
}

const ContinuousContacts& ContinuousSelfCollisionDetector::detect(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  vf_keys_.clear();
  ee_keys_.clear();
  tri_pairs_.clear();
  tests_ = kinetic_pairs_ = 0;
  vsw_.resize(x0.size());
  for (std::size_t v = 0; v < x0.size(); ++v) {
    for (int c = 0; c < 3; ++c) {
      vsw_[v].b[c] = std::min(x0[v][c], x1[v][c]);
      vsw_[v].b[c + 3] = std::max(x0[v][c], x1[v][c]);
    }
  }
  esw_.resize(edges_.size());
  for (std::size_t e = 0; e < edges_.size(); ++e) esw_[e] = merged(vsw_[edges_[e][0]], vsw_[edges_[e][1]]);
  tbox_.resize(tris_.size());
  tsw_.resize(tris_.size());
  for (std::size_t t = 0; t < tris_.size(); ++t) {
    const std::array<int, 3>& tri = tris_[t];
    double* b0 = tbox_[t].data();
    double* b1 = b0 + 6;
    point_box(b0, x0[tri[0]]);
    point_box(b1, x1[tri[0]]);
    for (int k = 1; k < 3; ++k) {
      extend(b0, x0[tri[k]]);
      extend(b1, x1[tri[k]]);
    }
    tsw_[t] = merged(merged(vsw_[tri[0]], vsw_[tri[1]]), vsw_[tri[2]]);
  }
  // The tree sees the motion in a frame moving with the mean displacement D: contact is the
  // same when every point at time t is moved by -t D, and the tree's float boxes are rounded
  // outward by far more than the rounding of x1 - D.
  Vec3 mean = Vec3::Zero();
  for (std::size_t v = 0; v < x0.size(); ++v) mean += x1[v] - x0[v];
  if (!x0.empty()) mean /= static_cast<double>(x0.size());
  moved_.resize(x1.size());
  for (std::size_t v = 0; v < x1.size(); ++v) moved_[v] = x1[v] - mean;
  bvh_.refit(x0, moved_);
  bvh_.overlapping_pairs(tri_pairs_);  // pairs sharing no vertex; neighbours are listed
  // Every feature's boxes lie in its triangle's, so triangles whose kinetic boxes never meet
  // have no feature pair that may touch.
  const int np = static_cast<int>(tri_pairs_.size());
  tri_disjoint_.resize(tri_pairs_.size());
  ccd_batch_kinetic_boxes(tbox_.data(), tri_pairs_.data(), np, tri_disjoint_.data(), width_);
  for (int k = 0; k < np; ++k) {
    if (tri_disjoint_[k]) continue;
    ++kinetic_pairs_;
    test_pair(tri_pairs_[k][0], tri_pairs_[k][1], x0, x1);
  }
  for (std::size_t k = 0; k < near_vf_keys_.size(); ++k) {
    const std::uint64_t key = near_vf_keys_[k];
    if (swept_overlap(vsw_[key >> 32].b, tsw_[key & 0xFFFFFFFFu].b))
      push(CcdKind::VertexFace, near_vf_points_[k], key, x0, x1);
  }
  for (std::size_t k = 0; k < near_ee_keys_.size(); ++k) {
    const std::uint64_t key = near_ee_keys_[k];
    if (swept_overlap(esw_[key >> 32].b, esw_[key & 0xFFFFFFFFu].b))
      push(CcdKind::EdgeEdge, near_ee_points_[k], key, x0, x1);
  }
  flush(x0, x1);
  emit_sorted();
  return out_;
}

void ContinuousSelfCollisionDetector::emit_sorted() {
  // Sorting the packed keys sorts the pairs: (v, f) lexicographically, and edge pairs by their
  // ids, which follow the edges' lexicographic order.
  std::sort(vf_keys_.begin(), vf_keys_.end());
  std::sort(ee_keys_.begin(), ee_keys_.end());
  out_.vertex_face.resize(vf_keys_.size());
  for (std::size_t k = 0; k < vf_keys_.size(); ++k)
    out_.vertex_face[k] = {static_cast<int>(vf_keys_[k] >> 32), static_cast<int>(vf_keys_[k] & 0xFFFFFFFFu)};
  out_.edge_edge.resize(ee_keys_.size());
  for (std::size_t k = 0; k < ee_keys_.size(); ++k)
    out_.edge_edge[k] = {edges_[ee_keys_[k] >> 32], edges_[ee_keys_[k] & 0xFFFFFFFFu]};
}

ContinuousContacts continuous_self_collision(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                                             const std::vector<std::array<int, 3>>& triangles, CcdTest test) {
  ContinuousSelfCollisionDetector d(triangles, x0, test);
  return d.detect(x0, x1);
}

ContinuousContacts filter_contacts(const ContinuousContacts& contacts, const std::vector<Vec3>& x0,
                                   const std::vector<Vec3>& x1, const std::vector<std::array<int, 3>>& triangles,
                                   const std::function<bool(const CcdQuery&)>& keep) {
  ContinuousContacts out;
  for (const auto& vf : contacts.vertex_face)
    if (keep(vertex_face_query(x0, x1, vf[0], triangles[vf[1]]))) out.vertex_face.push_back(vf);
  for (const auto& ee : contacts.edge_edge)
    if (keep(edge_edge_query(x0, x1, ee[0], ee[1]))) out.edge_edge.push_back(ee);
  return out;
}

}  // namespace tecido
