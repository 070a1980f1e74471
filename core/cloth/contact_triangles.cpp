#include "core/cloth/contact_triangles.h"

#include <algorithm>

namespace tecido {

namespace {

bool share_vertex(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  for (int u : a)
    for (int v : b)
      if (u == v) return true;
  return false;
}

bool has_vertex(const std::array<int, 3>& t, int v) { return t[0] == v || t[1] == v || t[2] == v; }

void push(int i, int j, std::vector<TrianglePair>& out) { out.push_back(i < j ? TrianglePair{i, j} : TrianglePair{j, i}); }

}  // namespace

VertexTriangles build_vertex_triangles(int vertex_count, const std::vector<std::array<int, 3>>& triangles) {
  VertexTriangles vt;
  vt.start.assign(static_cast<std::size_t>(vertex_count) + 1, 0);
  for (const auto& t : triangles)
    for (int v : t) ++vt.start[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 0; v < static_cast<std::size_t>(vertex_count); ++v) vt.start[v + 1] += vt.start[v];
  vt.tris.resize(static_cast<std::size_t>(vt.start.back()));
  std::vector<int> fill(vt.start.begin(), vt.start.end() - 1);
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (int v : triangles[i]) vt.tris[static_cast<std::size_t>(fill[v]++)] = static_cast<int>(i);
  return vt;
}

void contact_triangle_pairs(const ContinuousContacts& c, const std::vector<std::array<int, 3>>& triangles,
                            const VertexTriangles& vt, std::vector<TrianglePair>& out) {
  out.clear();
  for (const auto& [v, f] : c.vertex_face)
    for (int k = vt.start[v]; k < vt.start[v + 1]; ++k) {
      const int t = vt.tris[k];
      if (!share_vertex(triangles[t], triangles[f])) push(t, f, out);
    }
  for (const auto& [e, g] : c.edge_edge)
    for (int k = vt.start[e[0]]; k < vt.start[e[0] + 1]; ++k) {
      const int t = vt.tris[k];
      if (!has_vertex(triangles[t], e[1])) continue;  // t has edge e
      for (int m = vt.start[g[0]]; m < vt.start[g[0] + 1]; ++m) {
        const int u = vt.tris[m];
        if (has_vertex(triangles[u], g[1]) && !share_vertex(triangles[t], triangles[u])) push(t, u, out);
      }
    }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace tecido
