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
  const std::size_t nc = candidates_.size();
  std::size_t k = 0;
  // (Vertex offsets 3 * v are 32-bit gather indices: the batch needs fewer than 2^29 vertices.)
  if (nc >= 8 && test_ == default_tri_tri_test() && tri_tri_reject8_available() &&
      x.size() < (std::size_t{1} << 29)) {
    // Most candidates are mesh neighbours lying wholly on one side of each other's plane. The
    // first step of tri_tri_intersect (p's corners against q's plane, static filter) runs on
    // eight pairs at once; the pairs it certifies disjoint are dropped (tri_tri_intersect
    // would return false for them), the others get the full exact test. Same output.
    // Where it rejects nothing (coplanar neighbours of a flat cloth: the filter cannot decide
    // a point on the plane) it is pure overhead: after a block with no rejection, the next
    // kSkip blocks go straight to the full test.
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "x is read as packed doubles");
    constexpr int kSkip = 8;
    int skip = 0;
    const double* xd = reinterpret_cast<const double*>(x.data());
    int pv[3][8], qv[3][8];
    for (; k + 8 <= nc; k += 8) {
      // The candidates' triangles and corners are scattered over tris_ and x: fetch those of
      // the blocks ahead while this one is tested (indices two blocks ahead, corners one).
      for (std::size_t j = k + 16; j < std::min(k + 24, nc); ++j) {
        __builtin_prefetch(&tris_[candidates_[j][0]]);
        __builtin_prefetch(&tris_[candidates_[j][1]]);
      }
      for (std::size_t j = k + 8; j < std::min(k + 16, nc); ++j) {
        for (int side = 0; side < 2; ++side) {
          const std::array<int, 3>& t = tris_[candidates_[j][side]];
          __builtin_prefetch(&x[t[0]]);
          __builtin_prefetch(&x[t[2]]);
        }
      }
      unsigned keep = 0xFFu;
      if (skip > 0) {
        --skip;
      } else {
        for (int lane = 0; lane < 8; ++lane) {
          const std::array<int, 3>& p = tris_[candidates_[k + lane][0]];
          const std::array<int, 3>& q = tris_[candidates_[k + lane][1]];
          for (int i = 0; i < 3; ++i) {
            pv[i][lane] = 3 * p[i];
            qv[i][lane] = 3 * q[i];
          }
        }
        const unsigned reject = tri_tri_reject8(xd, pv, qv);
        if (reject == 0) skip = kSkip;
        keep = ~reject & 0xFFu;
      }
      for (; keep; keep &= keep - 1) {
        const TrianglePair& c = candidates_[k + static_cast<std::size_t>(__builtin_ctz(keep))];
        if (tri_tri_intersect(corners(x, tris_[c[0]]), corners(x, tris_[c[1]]))) pairs_.push_back(c);
      }
    }
  }
  for (; k < nc; ++k) {
    const TrianglePair& c = candidates_[k];
    if (test_(corners(x, tris_[c[0]]), corners(x, tris_[c[1]]))) pairs_.push_back(c);
  }
  std::sort(pairs_.begin(), pairs_.end());
  return pairs_;
}

std::vector<TrianglePair> self_collision_pairs(const std::vector<Vec3>& x,
                                               const std::vector<std::array<int, 3>>& triangles, TriTriTest test) {
  SelfCollisionDetector d(triangles, x, test);
  return d.detect(x);
}

}  // namespace tecido
