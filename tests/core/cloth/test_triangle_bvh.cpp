// TriangleBvh's two-frame query (core/cloth/triangle_bvh.h, moving_pairs): a subset of the
// swept-box pairs, in their order, the same on the SSE2 and AVX-512 paths, and never missing
// a pair whose triangles' boxes overlap at some time of the motion. The truth is sampled on
// dyadic motions (coordinates multiples of 2^-12 scaled by a power of two, times k / 64), where
// the interpolated positions are exact doubles.
#include "core/cloth/triangle_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

namespace tecido {
namespace {

struct Motion {
  std::vector<Vec3> x0, x1;
  std::vector<std::array<int, 3>> tris;
};

/// An n x n grid crumpled at random, moved by a random dyadic displacement of up to `reach`
/// per coordinate and a common drift; everything scaled by `scale` (a power of two).
Motion make_motion(int n, double reach, double scale, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> q(-4096, 4096);
  auto dyadic = [&](double r) { return r * q(rng) / 4096.0; };
  Motion m;
  const double h = 1.0 / (n - 1);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) m.x0.emplace_back(c * h + dyadic(0.25 * h), r * h + dyadic(0.25 * h), dyadic(0.5 * h));
  for (int r = 0; r + 1 < n; ++r) {
    for (int c = 0; c + 1 < n; ++c) {
      const int a = r * n + c;
      m.tris.push_back({a, a + 1, a + n + 1});
      m.tris.push_back({a, a + n + 1, a + n});
    }
  }
  const Vec3 drift(dyadic(1.0), dyadic(1.0), dyadic(1.0));
  for (const Vec3& p : m.x0) m.x1.push_back(p + drift + Vec3(dyadic(reach), dyadic(reach), dyadic(reach)));
  for (auto* x : {&m.x0, &m.x1})
    for (Vec3& p : *x) p *= scale;
  return m;
}

bool share_vertex(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  for (int u : a)
    for (int v : b)
      if (u == v) return true;
  return false;
}

/// The pairs (sharing no vertex) whose triangles' boxes overlap at some t = k / 64 (exact).
std::set<std::array<int, 2>> sampled_truth(const Motion& m) {
  std::set<std::array<int, 2>> truth;
  const int nt = static_cast<int>(m.tris.size());
  for (int k = 0; k <= 64; ++k) {
    const double t = k / 64.0;
    std::vector<std::array<double, 6>> box(nt);
    for (int i = 0; i < nt; ++i) {
      for (int c = 0; c < 3; ++c) {
        box[i][c] = INFINITY;
        box[i][c + 3] = -INFINITY;
        for (int v : m.tris[i]) {
          const double p = (1.0 - t) * m.x0[v][c] + t * m.x1[v][c];
          box[i][c] = std::min(box[i][c], p);
          box[i][c + 3] = std::max(box[i][c + 3], p);
        }
      }
    }
    for (int i = 0; i < nt; ++i) {
      for (int j = i + 1; j < nt; ++j) {
        bool o = !share_vertex(m.tris[i], m.tris[j]);
        for (int c = 0; c < 3 && o; ++c) o = box[i][c] <= box[j][c + 3] && box[j][c] <= box[i][c + 3];
        if (o) truth.insert({i, j});
      }
    }
  }
  return truth;
}

TEST(TriangleBvh, MovingPairsKeepEveryPairWhoseBoxesMeetAtASampledTime) {
  std::size_t kept = 0, dropped = 0;
  int seed = 1;
  for (double scale : {0x1p-60, 1.0, 0x1p60}) {
    for (double reach : {0.0, 0.01, 0.1, 0.5}) {
      const Motion m = make_motion(9, reach, scale, seed++);
      TriangleBvh wide, narrow;
      wide.build(m.x0, m.tris);
      narrow.build(m.x0, m.tris);
      narrow.set_use_wide_kernel(false);
      wide.refit(m.x0, m.x1);
      narrow.refit(m.x0, m.x1);
      std::vector<std::array<int, 2>> moving, moving_narrow, swept;
      wide.moving_pairs(moving);
      narrow.moving_pairs(moving_narrow);
      wide.overlapping_pairs(swept);
      EXPECT_EQ(moving, moving_narrow) << "scale " << scale << " reach " << reach;
      // A subsequence of the swept-box pairs.
      std::size_t at = 0;
      for (const auto& p : moving) {
        while (at < swept.size() && swept[at] != p) ++at;
        ASSERT_LT(at, swept.size()) << "not a swept pair, or out of order";
      }
      const std::set<std::array<int, 2>> got(moving.begin(), moving.end());
      for (const auto& p : sampled_truth(m)) EXPECT_TRUE(got.count(p)) << p[0] << ", " << p[1] << " scale " << scale;
      kept += moving.size();
      dropped += swept.size() - moving.size();
    }
  }
  EXPECT_GT(dropped, kept / 10);  // the kinetic test does prune
}

TEST(TriangleBvh, MovingPairsKeepPairsThatGrazeAtOneInstant) {
  // Pairs of triangles whose boxes touch at exactly one time t* = k / 8 (a corner of one box
  // meets a face of the other: along axis p the second closes in and touches at t*, along axis
  // q it recedes and leaves at t*), at scales 2^-70 .. 2^70: every such pair must be kept.
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<int> pick(0, 2), k8(1, 7), grid(-64, 64);
  for (double scale : {0x1p-70, 1.0, 0x1p70}) {
    Motion m;
    for (int i = 0; i < 300; ++i) {
      const int p = pick(rng), q = (p + 1 + pick(rng) % 2) % 3;
      const double ts = k8(rng) / 8.0;
      Vec3 lo(grid(rng) / 16.0, grid(rng) / 16.0, grid(rng) / 16.0), hi = lo + Vec3(0.5, 0.5, 0.5);
      // The second box: the same size; along p it starts 1 beyond hi and ends at
      // hi - 1 + ... linear, with lo_p(t*) = hi_p; along q its hi_q(t*) = lo_q, receding.
      Vec3 b0 = lo, b1 = lo;
      b0[p] = hi[p] + ts;  // lo_p(t) = hi_p + ts - t: touches at t = ts
      b1[p] = hi[p] + ts - 1.0;
      b0[q] = lo[q] - 0.5 + ts;  // hi_q(t) = lo_q + ts - t: meets lo_q at t = ts, then leaves
      b1[q] = lo[q] - 0.5 + ts - 1.0;
      const int base = static_cast<int>(m.x0.size());
      // A triangle spanning each box (corner, and the far ends along two axes).
      for (const auto& [c0, c1] : {std::pair<Vec3, Vec3>{lo, lo}, std::pair<Vec3, Vec3>{b0, b1}}) {
        m.x0.push_back(c0);
        m.x1.push_back(c1);
        m.x0.push_back(c0 + Vec3(0.5, 0.5, 0.0));
        m.x1.push_back(c1 + Vec3(0.5, 0.5, 0.0));
        m.x0.push_back(c0 + Vec3(0.0, 0.0, 0.5));
        m.x1.push_back(c1 + Vec3(0.0, 0.0, 0.5));
      }
      m.tris.push_back({base, base + 1, base + 2});
      m.tris.push_back({base + 3, base + 4, base + 5});
    }
    for (auto* x : {&m.x0, &m.x1})
      for (Vec3& v : *x) v *= scale;
    for (bool wide : {true, false}) {
      TriangleBvh bvh;
      bvh.build(m.x0, m.tris);
      bvh.set_use_wide_kernel(wide);
      bvh.refit(m.x0, m.x1);
      std::vector<std::array<int, 2>> moving;
      bvh.moving_pairs(moving);
      const std::set<std::array<int, 2>> got(moving.begin(), moving.end());
      for (int i = 0; i < 300; ++i)
        EXPECT_TRUE(got.count({2 * i, 2 * i + 1})) << "pair " << i << " scale " << scale << " wide " << wide;
    }
  }
}

}  // namespace
}  // namespace tecido
