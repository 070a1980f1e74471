#include "core/cloth/continuous_self_collision.h"

#include "core/cloth/mesh_topology.h"
#include "core/geometry/ccd.h"

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

/// True when the closed boxes [lo, hi] (lo xyz, hi xyz) overlap.
bool boxes_overlap(const std::array<double, 6>& a, const std::array<double, 6>& b) {
  return a[0] <= b[3] && b[0] <= a[3] && a[1] <= b[4] && b[1] <= a[4] && a[2] <= b[5] && b[2] <= a[5];
}

std::array<double, 6> united(const std::array<double, 6>& a, const std::array<double, 6>& b) {
  return {std::min(a[0], b[0]), std::min(a[1], b[1]), std::min(a[2], b[2]),
          std::max(a[3], b[3]), std::max(a[4], b[4]), std::max(a[5], b[5])};
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
  bvh_.build(x_build, tris_);
}

void ContinuousSelfCollisionDetector::test_pair(int i, int j, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  const Owned& oi = owned_[i];
  const Owned& oj = owned_[j];
  const std::array<int, 3>& ti = tris_[i];
  const std::array<int, 3>& tj = tris_[j];
  const std::array<double, 6> bi = united(united(vbox_[ti[0]], vbox_[ti[1]]), vbox_[ti[2]]);
  const std::array<double, 6> bj = united(united(vbox_[tj[0]], vbox_[tj[1]]), vbox_[tj[2]]);
  // Vertices of one triangle against the other face.
  for (int side = 0; side < 2; ++side) {
    const Owned& o = side == 0 ? oi : oj;
    const std::array<int, 3>& face = side == 0 ? tj : ti;
    const std::array<double, 6>& fbox = side == 0 ? bj : bi;
    const int f = side == 0 ? j : i;
    for (int k = 0; k < o.vertices; ++k) {
      const int v = o.vertex[k];
      if (has_vertex(face, v) || !boxes_overlap(vbox_[v], fbox)) continue;
      ++tests_;
      if (test_(vertex_face_query(x0, x1, v, face)).hit) out_.vertex_face.push_back({v, f});
    }
  }
  // Edges of one against edges of the other.
  for (int a = 0; a < oi.edge_count; ++a) {
    const MeshEdge& e = edges_[oi.edge[a]];
    const std::array<double, 6> be = united(vbox_[e[0]], vbox_[e[1]]);
    if (!boxes_overlap(be, bj)) continue;
    for (int b = 0; b < oj.edge_count; ++b) {
      const MeshEdge& g = edges_[oj.edge[b]];
      if (share_vertex(e, g) || !boxes_overlap(be, united(vbox_[g[0]], vbox_[g[1]]))) continue;
      ++tests_;
      // The query in the pair's own order (as the brute force builds it): same answer.
      const EdgeEdgePair pair = ordered(e, g);
      if (test_(edge_edge_query(x0, x1, pair[0], pair[1])).hit) out_.edge_edge.push_back(pair);
    }
  }
}

const ContinuousContacts& ContinuousSelfCollisionDetector::detect(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1) {
  out_.vertex_face.clear();
  out_.edge_edge.clear();
  tri_pairs_.clear();
  tests_ = 0;
  vbox_.resize(x0.size());
  for (std::size_t v = 0; v < x0.size(); ++v) {
    const Vec3 lo = x0[v].cwiseMin(x1[v]), hi = x0[v].cwiseMax(x1[v]);
    vbox_[v] = {lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z()};
  }
  bvh_.refit(x0, x1);
  bvh_.overlapping_pairs_with_neighbours(tri_pairs_);
  for (const auto& p : tri_pairs_) test_pair(p[0], p[1], x0, x1);
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
