#include "core/cloth/self_collision.h"

#include "core/geometry/tri_tri_intersect.h"
#include "core/platform/parallel_parts.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace tecido {

namespace {
Triangle corners(const std::vector<Vec3>& x, const std::array<int, 3>& t) { return {x[t[0]], x[t[1]], x[t[2]]}; }

bool share_vertex(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  for (int u : a)
    for (int v : b)
      if (u == v) return true;
  return false;
}
/// Whether the corners of t with coordinate a equal to level_t have boxes, over the two other
/// axes, apart from those of u's corners with coordinate a equal to level_u (a strict gap on one
/// axis).
bool faces_on_plane_apart(const Triangle& t, double level_t, const Triangle& u, double level_u, int a) {
  for (int b = 0; b < 3; ++b) {
    if (b == a) continue;
    double tlo = HUGE_VAL, thi = -HUGE_VAL, ulo = HUGE_VAL, uhi = -HUGE_VAL;
    for (int i = 0; i < 3; ++i) {
      if (t[i][a] == level_t) tlo = std::min(tlo, t[i][b]), thi = std::max(thi, t[i][b]);
      if (u[i][a] == level_u) ulo = std::min(ulo, u[i][b]), uhi = std::max(uhi, u[i][b]);
    }
    if (thi < ulo || uhi < tlo) return true;
  }
  return false;
}

/// True when the closed triangles p and q certainly do not intersect because their boxes meet
/// only on a plane x_a = X0 (X0 the largest coordinate a of one triangle and the smallest of the
/// other): every common point would lie there, where each triangle is the hull of its corners
/// with coordinate X0, and those hulls' boxes are apart. Comparisons of coordinates only, so
/// exact; false decides nothing (the exact test follows). The common case of a flat, grid-aligned
/// cloth: neighbouring cells' triangles whose boxes share a side or a corner.
bool apart_where_boxes_touch(const Triangle& p, const Triangle& q) {
  const Vec3 pmin = p[0].cwiseMin(p[1]).cwiseMin(p[2]), pmax = p[0].cwiseMax(p[1]).cwiseMax(p[2]);
  const Vec3 qmin = q[0].cwiseMin(q[1]).cwiseMin(q[2]), qmax = q[0].cwiseMax(q[1]).cwiseMax(q[2]);
  for (int a = 0; a < 3; ++a) {
    if (pmax[a] == qmin[a] && faces_on_plane_apart(p, pmax[a], q, qmin[a], a)) return true;
    if (qmax[a] == pmin[a] && faces_on_plane_apart(q, qmax[a], p, pmin[a], a)) return true;
  }
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
  bvh_.overlapping_pairs(candidates_, threads_);
  pairs_.clear();
  // A thread is started per share: below a few thousand candidates a share costs less than a start.
  const int parts = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads_), 1 + candidates_.size() / 4096));
  parts_ = parts;
  if (parts == 1) {
    narrow_phase(x, 0, candidates_.size(), pairs_);
  } else {
    // Contiguous chunks of the candidates (16 per thread), each taken by whichever thread is
    // free: contact-dense stretches of the list cost more than the rest. The pairs found,
    // merged and sorted, are the same whichever thread found them.
    if (static_cast<int>(part_pairs_.size()) < parts) part_pairs_.resize(static_cast<std::size_t>(parts));
    const std::size_t nc = candidates_.size();
    const int chunks = 16 * parts;
    std::atomic<int> next{0};
    run_parts(parts, [&](int part) {
      std::vector<TrianglePair>& out = part_pairs_[static_cast<std::size_t>(part)];
      out.clear();
      for (int c; (c = next.fetch_add(1, std::memory_order_relaxed)) < chunks;)
        narrow_phase(x, share_begin(nc, c, chunks), share_begin(nc, c + 1, chunks), out);
    });
    for (int part = 0; part < parts; ++part)
      pairs_.insert(pairs_.end(), part_pairs_[static_cast<std::size_t>(part)].begin(),
                    part_pairs_[static_cast<std::size_t>(part)].end());
  }
  std::sort(pairs_.begin(), pairs_.end());
  return pairs_;
}

void SelfCollisionDetector::narrow_phase(const std::vector<Vec3>& x, std::size_t begin, std::size_t end,
                                         std::vector<TrianglePair>& out) const {
  const std::size_t nc = end;  // candidates [begin, end)
  std::size_t k = begin;
  // (Vertex offsets 3 * v are 32-bit gather indices: the batch needs fewer than 2^29 vertices.)
  if (nc - begin >= 8 && test_ == default_tri_tri_test() && tri_tri_reject8_available() &&
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
        const Triangle p = corners(x, tris_[c[0]]), q = corners(x, tris_[c[1]]);
        if (!apart_where_boxes_touch(p, q) && tri_tri_intersect(p, q)) out.push_back(c);
      }
    }
  }
  // The exact test's answer is "apart" wherever apart_where_boxes_touch says so; another test
  // (the seed's) is asked every candidate, as self_collision_pairs_brute asks it.
  const bool exact = test_ == default_tri_tri_test();
  for (; k < nc; ++k) {
    const TrianglePair& c = candidates_[k];
    const Triangle p = corners(x, tris_[c[0]]), q = corners(x, tris_[c[1]]);
    if (exact && apart_where_boxes_touch(p, q)) continue;
    if (test_(p, q)) out.push_back(c);
  }
}

std::vector<TrianglePair> self_collision_pairs(const std::vector<Vec3>& x,
                                               const std::vector<std::array<int, 3>>& triangles, TriTriTest test) {
  SelfCollisionDetector d(triangles, x, test);
  return d.detect(x);
}

}  // namespace tecido
