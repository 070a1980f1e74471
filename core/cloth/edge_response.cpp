#include "core/cloth/edge_response.h"

#include <cmath>

namespace tecido {

BorderNeighbours border_neighbours(const MeshTopology& topo, const std::vector<Vec3>& x, int i) {
  BorderNeighbours b{x[i], x[i]};
  const int begin = topo.adj_start[i], end = topo.adj_start[i + 1];
  if (begin == end) return b;
  // border_distance is -1 for a closed piece: every neighbour then ties.
  int lo = topo.border_distance[topo.adj[begin]], hi = lo;
  for (int k = begin + 1; k < end; ++k) {
    const int d = topo.border_distance[topo.adj[k]];
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  Vec3 sum_lo = Vec3::Zero(), sum_hi = Vec3::Zero();
  int n_lo = 0, n_hi = 0;
  for (int k = begin; k < end; ++k) {
    const int j = topo.adj[k];
    const int d = topo.border_distance[j];
    if (d == lo) {
      sum_lo += x[j];
      ++n_lo;
    }
    if (d == hi) {
      sum_hi += x[j];
      ++n_hi;
    }
  }
  b.nearer = sum_lo / static_cast<double>(n_lo);
  b.farther = sum_hi / static_cast<double>(n_hi);
  return b;
}

Vec3 edge_mode_direction(EdgeMode mode, const MeshTopology& topo, const std::vector<Vec3>& x, int i) {
  const int begin = topo.adj_start[i], end = topo.adj_start[i + 1];
  if (begin == end) return Vec3::Zero();
  double scale = 0.0;
  for (int k = begin; k < end; ++k) scale += (x[topo.adj[k]] - x[i]).norm();
  scale /= static_cast<double>(end - begin);
  const BorderNeighbours b = border_neighbours(topo, x, i);
  Vec3 d;
  switch (mode) {
    case EdgeMode::AwayFromNearer: d = x[i] - b.nearer; break;
    case EdgeMode::TowardFarther: d = b.farther - x[i]; break;
    case EdgeMode::TowardMidpoint: d = 0.5 * (b.farther + b.nearer) - x[i]; break;
    default: return Vec3::Zero();
  }
  const double len = d.norm();
  if (!(len > 1e-9 * scale) || !std::isfinite(len)) return Vec3::Zero();
  return d / len;
}

int apply_edge_mode(EdgeMode mode, const MeshTopology& topo, const std::vector<std::array<int, 3>>& triangles,
                    const std::vector<TrianglePair>& pairs, const std::uint8_t* skip_pair, const std::vector<Vec3>& x,
                    const std::vector<double>& inv_mass, double strength, double dt, std::vector<Vec3>& v,
                    std::vector<std::uint8_t>& mark) {
  mark.assign(x.size(), 0);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (skip_pair && skip_pair[k]) continue;
    for (int t : pairs[k])
      for (int i : triangles[t]) mark[i] = 1;
  }
  int pushed = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!mark[i] || inv_mass[i] == 0.0) continue;
    const Vec3 d = edge_mode_direction(mode, topo, x, static_cast<int>(i));
    if (d == Vec3::Zero()) continue;
    v[i] += (strength * dt * inv_mass[i]) * d;
    ++pushed;
  }
  return pushed;
}

}  // namespace tecido
