#include "core/geometry/mesh_edges.h"

#include "core/geometry/orient_predicates.h"

#include <algorithm>
#include <tuple>

namespace tecido {

std::vector<std::array<int, 2>> mesh_feature_edges(const std::vector<Vec3>& vertices,
                                                   const std::vector<std::array<int, 3>>& triangles) {
  // (edge, triangle) for every triangle side, grouped by edge.
  std::vector<std::tuple<int, int, int>> sides;
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = triangles[f][k], b = triangles[f][(k + 1) % 3];
      sides.emplace_back(std::min(a, b), std::max(a, b), static_cast<int>(f));
    }
  std::sort(sides.begin(), sides.end());
  std::vector<std::array<int, 2>> out;
  for (std::size_t lo = 0; lo < sides.size();) {
    std::size_t hi = lo;
    while (hi < sides.size() && std::get<0>(sides[hi]) == std::get<0>(sides[lo]) &&
           std::get<1>(sides[hi]) == std::get<1>(sides[lo]))
      ++hi;
    bool feature = hi - lo == 1;  // a border
    const auto& t0 = triangles[static_cast<std::size_t>(std::get<2>(sides[lo]))];
    for (std::size_t k = lo + 1; k < hi && !feature; ++k)
      for (int c : triangles[static_cast<std::size_t>(std::get<2>(sides[k]))])
        if (orient3d_sign(vertices[t0[0]], vertices[t0[1]], vertices[t0[2]], vertices[c]) != 0) feature = true;
    if (feature) out.push_back({std::get<0>(sides[lo]), std::get<1>(sides[lo])});
    lo = hi;
  }
  return out;
}

}  // namespace tecido
