#include "core/cloth/self_collision.h"

#include "core/geometry/tri_tri_intersect.h"

#include <algorithm>

namespace tecido {

namespace {
Triangle corners(const std::vector<Vec3>& x, const std::array<int, 3>& t) { return {x[t[0]], x[t[1]], x[t[2]]}; }

bool share_vertex(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  for (int u : a)
    for (int v : b)
      if (u == v) return true;
  return false;
}
}  // namespace

TriTriTest default_tri_tri_test() { return &tri_tri_intersect; }

std::vector<TrianglePair> self_collision_pairs_brute(const std::vector<Vec3>& x,
                                                     const std::vector<std::array<int, 3>>& triangles,
                                                     TriTriTest test) {
  if (!test) test = default_tri_tri_test();
  std::vector<TrianglePair> out;
  const int n = static_cast<int>(triangles.size());
  for (int i = 0; i < n; ++i) {
    const Triangle ti = corners(x, triangles[i]);
    for (int j = i + 1; j < n; ++j) {
      if (share_vertex(triangles[i], triangles[j])) continue;
      if (test(ti, corners(x, triangles[j]))) out.push_back({i, j});
    }
  }
  return out;
}

SelfCollisionDetector::SelfCollisionDetector(const std::vector<std::array<int, 3>>& triangles,
                                             const std::vector<Vec3>& x_build, TriTriTest test)
    : tris_(triangles), test_(test ? test : default_tri_tri_test()) {
  bvh_.build(x_build, tris_);
}

const std::vector<TrianglePair>& SelfCollisionDetector::detect(const std::vector<Vec3>& x) {
  bvh_.refit(x);
  candidates_.clear();
  bvh_.overlapping_pairs(candidates_);
  pairs_.clear();
  for (const TrianglePair& c : candidates_)
    if (test_(corners(x, tris_[c[0]]), corners(x, tris_[c[1]]))) pairs_.push_back(c);
  std::sort(pairs_.begin(), pairs_.end());
  return pairs_;
}

std::vector<TrianglePair> self_collision_pairs(const std::vector<Vec3>& x,
                                               const std::vector<std::array<int, 3>>& triangles, TriTriTest test) {
  SelfCollisionDetector d(triangles, x, test);
  return d.detect(x);
}

}  // namespace tecido
