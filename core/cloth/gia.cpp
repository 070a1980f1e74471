#include "core/cloth/gia.h"

#include "core/geometry/orient_predicates.h"

#include <algorithm>
#include <cmath>

namespace tecido {

bool segment_pierces_triangle(const Vec3& p, const Vec3& q, const Triangle& t) {
  const int sp = orient3d_sign(t[0], t[1], t[2], p);
  const int sq = orient3d_sign(t[0], t[1], t[2], q);
  if (sp == 0 && sq == 0) return false;  // in the plane: no crossing
  if (sp == sq) return false;            // strictly on one side
  // The segment meets the plane in one point; it lies in the closed triangle when the line p-q
  // passes on the same side of (or through) the three edges.
  const int s0 = orient3d_sign(p, q, t[0], t[1]);
  const int s1 = orient3d_sign(p, q, t[1], t[2]);
  const int s2 = orient3d_sign(p, q, t[2], t[0]);
  const bool has_neg = s0 < 0 || s1 < 0 || s2 < 0;
  const bool has_pos = s0 > 0 || s1 > 0 || s2 > 0;
  return !(has_neg && has_pos);
}

void analyse_intersections(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles,
                           const MeshTopology& topo, const std::vector<TrianglePair>& pairs, GiaResult& out) {
  const int ne = static_cast<int>(topo.edges.size());
  const int nv = topo.vertex_count;
  GiaResult::Work& w = out.work;

  // 1. Cut edges: an edge of one triangle of a pair piercing the other triangle.
  out.cut.assign(ne, 0);
  out.cut_edges = 0;
  for (const TrianglePair& pr : pairs) {
    for (int side = 0; side < 2; ++side) {
      const auto& tb = triangles[pr[1 - side]];
      const Triangle other{x[tb[0]], x[tb[1]], x[tb[2]]};
      for (int s = 0; s < 3; ++s) {
        const int e = topo.tri_edges[pr[side]][s];
        if (out.cut[e]) continue;
        if (segment_pierces_triangle(x[topo.edges[e][0]], x[topo.edges[e][1]], other)) {
          out.cut[e] = 1;
          ++out.cut_edges;
        }
      }
    }
  }

  // 2. Components over uncut edges, labelled in order of their smallest vertex.
  out.component.assign(nv, -1);
  out.component_size.clear();
  w.queue.clear();
  for (int v0 = 0; v0 < nv; ++v0) {
    if (!topo.used[v0] || out.component[v0] >= 0) continue;
    const int c = static_cast<int>(out.component_size.size());
    out.component_size.push_back(0);
    w.queue.clear();
    w.queue.push_back(v0);
    out.component[v0] = c;
    for (std::size_t head = 0; head < w.queue.size(); ++head) {
      const int v = w.queue[head];
      ++out.component_size[c];
      for (int k = topo.adj_start[v]; k < topo.adj_start[v + 1]; ++k) {
        if (out.cut[topo.adj_edge[k]]) continue;
        const int u = topo.adj[k];
        if (out.component[u] < 0) {
          out.component[u] = c;
          w.queue.push_back(u);
        }
      }
    }
  }
  const int nc = static_cast<int>(out.component_size.size());

  // 3. Wrong-side regions: the smaller side of each separating cut edge.
  out.wrong_side.assign(nc, 0);
  out.unseparated_cut_edges = 0;
  out.ambiguous_cut_edges = 0;
  for (int e = 0; e < ne; ++e) {
    if (!out.cut[e]) continue;
    const int cu = out.component[topo.edges[e][0]], cv = out.component[topo.edges[e][1]];
    if (cu == cv) {
      ++out.unseparated_cut_edges;
    } else if (out.component_size[cu] == out.component_size[cv]) {
      ++out.ambiguous_cut_edges;
    } else {
      out.wrong_side[out.component_size[cu] < out.component_size[cv] ? cu : cv] = 1;
    }
  }
  out.regions.clear();
  for (int c = 0; c < nc; ++c)
    if (out.wrong_side[c]) out.regions.push_back(c);

  // 4. Pull directions: toward the partner regions (or the opposite triangles).
  out.pull.assign(nc, Vec3::Zero());
  out.pair_resolved.assign(pairs.size(), 0);
  out.unresolved_pairs = 0;
  if (out.regions.empty()) {
    out.unresolved_pairs = static_cast<int>(pairs.size());
    return;
  }
  w.centroid.assign(nc, Vec3::Zero());
  for (int v = 0; v < nv; ++v) {
    const int c = out.component[v];
    if (c >= 0 && out.wrong_side[c]) w.centroid[c] += x[v];
  }
  for (int c : out.regions) w.centroid[c] /= static_cast<double>(out.component_size[c]);
  w.fallback_sum.assign(nc, Vec3::Zero());
  w.fallback_count.assign(nc, 0);
  w.links.clear();
  auto regions_of = [&](int t, int* r) {
    int n = 0;
    for (int v : triangles[t]) {
      const int c = out.component[v];
      if (!out.wrong_side[c]) continue;
      bool seen = false;
      for (int k = 0; k < n; ++k) seen = seen || r[k] == c;
      if (!seen) r[n++] = c;
    }
    return n;
  };
  auto touches = [&](int t, int c) {
    for (int v : triangles[t])
      if (out.component[v] == c) return true;
    return false;
  };
  for (const TrianglePair& pr : pairs) {
    int r1[3], r2[3];
    const int n1 = regions_of(pr[0], r1), n2 = regions_of(pr[1], r2);
    for (int a = 0; a < n1; ++a)
      for (int b = 0; b < n2; ++b)
        if (r1[a] != r2[b]) {
          w.links.push_back({r1[a], r2[b]});
          w.links.push_back({r2[b], r1[a]});
        }
    for (int side = 0; side < 2; ++side) {
      const int* rs = side == 0 ? r1 : r2;
      const int n = side == 0 ? n1 : n2;
      const int other = pr[1 - side];
      for (int a = 0; a < n; ++a) {
        if (touches(other, rs[a])) continue;
        for (int v : triangles[other]) w.fallback_sum[rs[a]] += x[v];
        w.fallback_count[rs[a]] += 3;
      }
    }
  }
  std::sort(w.links.begin(), w.links.end());
  w.links.erase(std::unique(w.links.begin(), w.links.end()), w.links.end());
  std::size_t k = 0;
  for (int c : out.regions) {
    Vec3 sum = Vec3::Zero();
    double weight = 0.0;
    while (k < w.links.size() && w.links[k][0] < c) ++k;
    for (; k < w.links.size() && w.links[k][0] == c; ++k) {
      const int p = w.links[k][1];
      sum += static_cast<double>(out.component_size[p]) * w.centroid[p];
      weight += out.component_size[p];
    }
    Vec3 target;
    if (weight > 0.0) {
      target = sum / weight;
    } else if (w.fallback_count[c] > 0) {
      target = w.fallback_sum[c] / static_cast<double>(w.fallback_count[c]);
    } else {
      continue;
    }
    const Vec3 d = target - w.centroid[c];
    const double len = d.norm();
    if (len > 0.0 && std::isfinite(len)) out.pull[c] = d / len;
  }

  // 5. Resolved pairs.
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    bool ok = false;
    for (int t : pairs[p])
      for (int v : triangles[t]) {
        const int c = out.component[v];
        ok = ok || (out.wrong_side[c] && out.pull[c] != Vec3::Zero());
      }
    out.pair_resolved[p] = ok ? 1 : 0;
    if (!ok) ++out.unresolved_pairs;
  }
}

}  // namespace tecido
