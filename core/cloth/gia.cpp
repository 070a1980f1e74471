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

namespace {

using Triangles = std::vector<std::array<int, 3>>;

/// Step 1. Cut edges: an edge of one triangle of a pair piercing the other triangle.
void mark_cut_edges(const std::vector<Vec3>& x, const Triangles& triangles, const MeshTopology& topo,
                    const std::vector<TrianglePair>& pairs, GiaResult& out) {
  out.cut.assign(topo.edges.size(), 0);
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
}

/// Step 2. Components over uncut edges (breadth-first flood fill), labelled in order of their
/// smallest vertex.
void label_components(const MeshTopology& topo, GiaResult& out) {
  const int nv = topo.vertex_count;
  std::vector<int>& queue = out.work.queue;
  out.component.assign(nv, -1);
  out.component_size.clear();
  for (int v0 = 0; v0 < nv; ++v0) {
    if (!topo.used[v0] || out.component[v0] >= 0) continue;
    const int c = static_cast<int>(out.component_size.size());
    out.component_size.push_back(0);
    queue.clear();
    queue.push_back(v0);
    out.component[v0] = c;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int v = queue[head];
      ++out.component_size[c];
      for (int k = topo.adj_start[v]; k < topo.adj_start[v + 1]; ++k) {
        if (out.cut[topo.adj_edge[k]]) continue;
        const int u = topo.adj[k];
        if (out.component[u] < 0) {
          out.component[u] = c;
          queue.push_back(u);
        }
      }
    }
  }
}

/// Step 3. Wrong-side regions: the smaller side of each separating cut edge (Baraff, Witkin and
/// Kass 2003 assume the smaller region is the one on the wrong side).
void mark_wrong_side(const MeshTopology& topo, GiaResult& out) {
  const int nc = static_cast<int>(out.component_size.size());
  out.wrong_side.assign(nc, 0);
  out.unseparated_cut_edges = 0;
  out.ambiguous_cut_edges = 0;
  for (std::size_t e = 0; e < topo.edges.size(); ++e) {
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
}

/// The distinct wrong-side regions among triangle t's vertices, into r (at most 3); returns how many.
int regions_of(const Triangles& triangles, const GiaResult& out, int t, int* r) {
  int n = 0;
  for (int v : triangles[t]) {
    const int c = out.component[v];
    if (!out.wrong_side[c]) continue;
    bool seen = false;
    for (int k = 0; k < n; ++k) seen = seen || r[k] == c;
    if (!seen) r[n++] = c;
  }
  return n;
}

bool touches(const Triangles& triangles, const GiaResult& out, int t, int c) {
  for (int v : triangles[t])
    if (out.component[v] == c) return true;
  return false;
}

/// Step 4a. For every intersecting pair: links between the wrong-side regions on its two
/// triangles (both directions), and, for a region whose partner triangle is not in it, the
/// partner's corners as a fallback target.
void link_regions(const std::vector<Vec3>& x, const Triangles& triangles, const std::vector<TrianglePair>& pairs,
                  GiaResult& out) {
  GiaResult::Work& w = out.work;
  const std::size_t nc = out.component_size.size();
  w.fallback_sum.assign(nc, Vec3::Zero());
  w.fallback_count.assign(nc, 0);
  w.links.clear();
  for (const TrianglePair& pr : pairs) {
    int r[2][3];
    const int n[2] = {regions_of(triangles, out, pr[0], r[0]), regions_of(triangles, out, pr[1], r[1])};
    for (int a = 0; a < n[0]; ++a)
      for (int b = 0; b < n[1]; ++b)
        if (r[0][a] != r[1][b]) {
          w.links.push_back({r[0][a], r[1][b]});
          w.links.push_back({r[1][b], r[0][a]});
        }
    for (int side = 0; side < 2; ++side) {
      const int other = pr[1 - side];
      for (int a = 0; a < n[side]; ++a) {
        if (touches(triangles, out, other, r[side][a])) continue;
        for (int v : triangles[other]) w.fallback_sum[r[side][a]] += x[v];
        w.fallback_count[r[side][a]] += 3;
      }
    }
  }
  std::sort(w.links.begin(), w.links.end());
  w.links.erase(std::unique(w.links.begin(), w.links.end()), w.links.end());
}

/// Step 4b. Pull directions: each wrong-side region toward the size-weighted centroid of its
/// partner regions, or else toward its fallback target.
void pull_directions(const std::vector<Vec3>& x, GiaResult& out) {
  GiaResult::Work& w = out.work;
  const std::size_t nc = out.component_size.size();
  w.centroid.assign(nc, Vec3::Zero());
  for (std::size_t v = 0; v < out.component.size(); ++v) {
    const int c = out.component[v];
    if (c >= 0 && out.wrong_side[c]) w.centroid[c] += x[v];
  }
  for (int c : out.regions) w.centroid[c] /= static_cast<double>(out.component_size[c]);
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
}

/// Step 5. A pair is resolved when one of its vertices lies in a wrong-side region with a pull.
void mark_resolved(const Triangles& triangles, const std::vector<TrianglePair>& pairs, GiaResult& out) {
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

}  // namespace

void analyse_intersections(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles,
                           const MeshTopology& topo, const std::vector<TrianglePair>& pairs, GiaResult& out) {
  mark_cut_edges(x, triangles, topo, pairs, out);
  label_components(topo, out);
  mark_wrong_side(topo, out);
  out.pull.assign(out.component_size.size(), Vec3::Zero());
  out.pair_resolved.assign(pairs.size(), 0);
  out.unresolved_pairs = 0;
  if (out.regions.empty()) {
    out.unresolved_pairs = static_cast<int>(pairs.size());
    return;
  }
  link_regions(x, triangles, pairs, out);
  pull_directions(x, out);
  mark_resolved(triangles, pairs, out);
}

}  // namespace tecido
