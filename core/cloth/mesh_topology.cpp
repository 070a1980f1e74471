#include "core/cloth/mesh_topology.h"

#include <algorithm>

namespace tecido {

MeshTopology build_mesh_topology(int vertex_count, const std::vector<std::array<int, 3>>& triangles) {
  MeshTopology t;
  t.vertex_count = vertex_count;
  const std::size_t nt = triangles.size();

  // Every (edge, triangle, slot) incidence, sorted by edge: unique edges and their ids.
  struct Inc {
    int u, v;
    int tri;
    int slot;
  };
  std::vector<Inc> inc;
  inc.reserve(3 * nt);
  for (std::size_t k = 0; k < nt; ++k) {
    for (int s = 0; s < 3; ++s) {
      int u = triangles[k][s], v = triangles[k][(s + 1) % 3];
      if (u > v) std::swap(u, v);
      inc.push_back({u, v, static_cast<int>(k), s});
    }
  }
  std::sort(inc.begin(), inc.end(), [](const Inc& a, const Inc& b) {
    if (a.u != b.u) return a.u < b.u;
    if (a.v != b.v) return a.v < b.v;
    if (a.tri != b.tri) return a.tri < b.tri;
    return a.slot < b.slot;
  });
  t.tri_edges.assign(nt, {-1, -1, -1});
  for (std::size_t k = 0; k < inc.size(); ++k) {
    if (k == 0 || inc[k].u != inc[k - 1].u || inc[k].v != inc[k - 1].v) {
      t.edges.push_back({inc[k].u, inc[k].v});
      t.edge_triangles.push_back(0);
    }
    const int e = static_cast<int>(t.edges.size()) - 1;
    t.tri_edges[inc[k].tri][inc[k].slot] = e;
    ++t.edge_triangles[e];
  }

  // Vertex adjacency (CSR), neighbours ascending.
  t.used.assign(vertex_count, 0);
  for (const auto& tri : triangles)
    for (int v : tri) t.used[v] = 1;
  std::vector<int> degree(vertex_count, 0);
  for (const auto& e : t.edges) {
    ++degree[e[0]];
    ++degree[e[1]];
  }
  t.adj_start.assign(vertex_count + 1, 0);
  for (int v = 0; v < vertex_count; ++v) t.adj_start[v + 1] = t.adj_start[v] + degree[v];
  t.adj.assign(t.adj_start[vertex_count], 0);
  t.adj_edge.assign(t.adj.size(), 0);
  std::vector<int> fill(t.adj_start.begin(), t.adj_start.end() - 1);
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    const int u = t.edges[e][0], v = t.edges[e][1];
    t.adj[fill[u]] = v;
    t.adj_edge[fill[u]++] = static_cast<int>(e);
    t.adj[fill[v]] = u;
    t.adj_edge[fill[v]++] = static_cast<int>(e);
  }
  // Neighbours ascend: edges arrive sorted by (u, v), so for vertex v first come the edges
  // (u, v) with u < v in order of u, then the edges (v, w) in order of w.

  // Border distance: multi-source BFS from boundary vertices.
  t.border_distance.assign(vertex_count, -1);
  std::vector<int> queue;
  queue.reserve(vertex_count);
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    if (t.edge_triangles[e] != 1) continue;
    for (int v : t.edges[e]) {
      if (t.border_distance[v] != 0) {
        t.border_distance[v] = 0;
        queue.push_back(v);
      }
    }
  }
  std::sort(queue.begin(), queue.end());
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int v = queue[head];
    for (int k = t.adj_start[v]; k < t.adj_start[v + 1]; ++k) {
      const int w = t.adj[k];
      if (t.border_distance[w] < 0) {
        t.border_distance[w] = t.border_distance[v] + 1;
        queue.push_back(w);
      }
    }
  }
  return t;
}

}  // namespace tecido
