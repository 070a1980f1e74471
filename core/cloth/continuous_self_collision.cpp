#include "core/cloth/continuous_self_collision.h"

#include "core/cloth/mesh_topology.h"
#include "core/geometry/ccd.h"
#include "core/geometry/ccd_kinetic_boxes.h"
#include "core/geometry/ccd_pipeline.h"

#include <algorithm>

namespace tecido {

namespace {

CcdAnswer default_test(const CcdQuery& q) { return ccd(q); }

bool has_vertex(const std::array<int, 3>& t, int v) { return t[0] == v || t[1] == v || t[2] == v; }

bool share_vertex(const MeshEdge& e, const MeshEdge& f) { return e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1]; }

EdgeEdgePair ordered(const MeshEdge& e, const MeshEdge& f) { return f < e ? EdgeEdgePair{f, e} : EdgeEdgePair{e, f}; }

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

/// The first stages of core's test (ccd_pipeline.cpp) on two primitives' boxes at both frames:
/// their swept boxes (the union of the two) overlap and their kinetic boxes are not certainly
/// disjoint. The boxes are those the pipeline computes from the query's points, so a pair
/// rejected here is one the test would reject.
template <class B>
bool may_touch(const B& a, const B& b) {
  for (int c = 0; c < 3; ++c) {
    const double alo = std::min(a.b0[c], a.b1[c]), ahi = std::max(a.b0[c + 3], a.b1[c + 3]);
    const double blo = std::min(b.b0[c], b.b1[c]), bhi = std::max(b.b0[c + 3], b.b1[c + 3]);
    if (ahi < blo || bhi < alo) return false;
  }
  return !ccd_kinetic_boxes_disjoint(a.b0, a.b1, b.b0, b.b1);
}

/// Swept boxes overlap (the cheap half of may_touch).
template <class B>
bool swept_overlap(const B& a, const B& b) {
  for (int c = 0; c < 3; ++c) {
    const double alo = std::min(a.b0[c], a.b1[c]), ahi = std::max(a.b0[c + 3], a.b1[c + 3]);
    const double blo = std::min(b.b0[c], b.b1[c]), bhi = std::max(b.b0[c + 3], b.b1[c + 3]);
    if (ahi < blo || bhi < alo) return false;
  }
  return true;
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
      for (int k = 0; k < o.vertices; ++k)
        if (!has_vertex(tris_[f], o.vertex[k])) near_vf_.push_back({o.vertex[k], f});
    }
    for (int a = 0; a < owned_[i].edge_count; ++a) {
      for (int b = 0; b < owned_[j].edge_count; ++b) {
        int ea = owned_[i].edge[a], eb = owned_[j].edge[b];
        if (share_vertex(edges_[ea], edges_[eb])) continue;
        if (edges_[eb] < edges_[ea]) std::swap(ea, eb);
        near_ee_.push_back({ea, eb});
      }
    }
  }
}

bool ContinuousSelfCollisionDetector::run(const CcdQuery& q) const {
  // Core's test: its box stages were just run here on the same boxes (may_touch), so go on
  // from the next stage (the same answer, without checking the boxes twice).
  return test_ == &default_test ? ccd_after_boxes(q).hit : test_(q).hit;
}

void ContinuousSelfCollisionDetector::test_pair(int i, int j, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  // Every feature's boxes lie in its triangle's, so triangles whose kinetic boxes never meet
  // have no feature pair that may touch.
  if (ccd_kinetic_boxes_disjoint(tbox_[i].b0, tbox_[i].b1, tbox_[j].b0, tbox_[j].b1)) return;
  ++kinetic_pairs_;
  const Owned& oi = owned_[i];
  const Owned& oj = owned_[j];
  // Vertices of one triangle against the other face.
  for (int side = 0; side < 2; ++side) {
    const Owned& o = side == 0 ? oi : oj;
    const int f = side == 0 ? j : i;
    const std::array<int, 3>& face = tris_[f];
    for (int k = 0; k < o.vertices; ++k) {
      const int v = o.vertex[k];
      if (has_vertex(face, v) || !may_touch(vbox_[v], tbox_[f])) continue;
      ++tests_;
      if (run(vertex_face_query(x0, x1, v, face))) out_.vertex_face.push_back({v, f});
    }
  }
  // Edges of one against edges of the other.
  for (int a = 0; a < oi.edge_count; ++a) {
    const int ea = oi.edge[a];
    if (!swept_overlap(ebox_[ea], tbox_[j])) continue;
    for (int b = 0; b < oj.edge_count; ++b) {
      const int eb = oj.edge[b];
      if (share_vertex(edges_[ea], edges_[eb]) || !may_touch(ebox_[ea], ebox_[eb])) continue;
      ++tests_;
      // The query in the pair's own order (as the brute force builds it): same answer.
      const EdgeEdgePair pair = ordered(edges_[ea], edges_[eb]);
      if (run(edge_edge_query(x0, x1, pair[0], pair[1]))) out_.edge_edge.push_back(pair);
    }
  }
}

const ContinuousContacts& ContinuousSelfCollisionDetector::detect(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  out_.vertex_face.clear();
  out_.edge_edge.clear();
  tri_pairs_.clear();
  tests_ = kinetic_pairs_ = 0;
  vbox_.resize(x0.size());
  for (std::size_t v = 0; v < x0.size(); ++v) {
    point_box(vbox_[v].b0, x0[v]);
    point_box(vbox_[v].b1, x1[v]);
  }
  ebox_.resize(edges_.size());
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    ebox_[e] = vbox_[edges_[e][0]];
    extend(ebox_[e].b0, x0[edges_[e][1]]);
    extend(ebox_[e].b1, x1[edges_[e][1]]);
  }
  tbox_.resize(tris_.size());
  for (std::size_t t = 0; t < tris_.size(); ++t) {
    tbox_[t] = vbox_[tris_[t][0]];
    for (int k = 1; k < 3; ++k) {
      extend(tbox_[t].b0, x0[tris_[t][k]]);
      extend(tbox_[t].b1, x1[tris_[t][k]]);
    }
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
  for (const auto& p : tri_pairs_) test_pair(p[0], p[1], x0, x1);
  for (const auto& [v, f] : near_vf_) {
    if (!may_touch(vbox_[v], tbox_[f])) continue;
    ++tests_;
    if (run(vertex_face_query(x0, x1, v, tris_[f]))) out_.vertex_face.push_back({v, f});
  }
  for (const auto& [ea, eb] : near_ee_) {
    if (!may_touch(ebox_[ea], ebox_[eb])) continue;
    ++tests_;
    if (run(edge_edge_query(x0, x1, edges_[ea], edges_[eb]))) out_.edge_edge.push_back({edges_[ea], edges_[eb]});
  }
  sort_contacts(out_);
  return out_;
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
