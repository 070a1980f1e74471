// TriangleBvh's queries on several threads (core/cloth/triangle_bvh.h): at 1, 2, 3 and 8
// threads the pair list is the one-thread list, pair for pair and in the same order, and as a
// set it is the brute-force answer over all triangle pairs (closed boxes computed here in
// double precision, pairs sharing a vertex left out). Coordinates are multiples of 2^-12 of
// magnitude below 4, so boxes that do not meet are at least 2^-12 apart, far more than the
// tree's outward float rounding (an ulp or two): the tree's answer is exactly the brute one.
#include "core/cloth/triangle_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>

namespace tecido {
namespace {

struct Mesh {
  std::vector<Vec3> x;
  std::vector<std::array<int, 3>> tris;
};

double dyadic(double v) { return std::round(v * 4096.0) / 4096.0; }

/// An n x n cloth of side 1 folded at u = 0.5 back over itself, 0.02 above, with a ripple of
/// 0.03: the layers cross along curves (bench/bench_self_collision.cpp's frame, snapped).
Mesh folded_cloth(int n) {
  Mesh m;
  const double pi = std::acos(-1.0);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      const double u = static_cast<double>(c) / (n - 1), v = static_cast<double>(r) / (n - 1);
      const double ripple = 0.03 * std::sin(9.0 * u + 1.0) * std::sin(7.0 * v);
      Vec3 p(u, v, ripple);
      if (u > 0.5) {
        const double a = (u - 0.5) / 0.02;
        p = a < pi ? Vec3(0.5 + 0.01 * std::sin(a), v, 0.01 - 0.01 * std::cos(a) + ripple)
                   : Vec3(0.5 - (u - 0.5 - 0.02 * pi), v, 0.02 - ripple);
      }
      m.x.emplace_back(dyadic(p.x()), dyadic(p.y()), dyadic(p.z()));
    }
  }
  for (int r = 0; r + 1 < n; ++r) {
    for (int c = 0; c + 1 < n; ++c) {
      const int a = r * n + c;
      m.tris.push_back({a, a + 1, a + n + 1});
      m.tris.push_back({a, a + n + 1, a + n});
    }
  }
  return m;
}

/// `count` random triangles, thin in x, in [0, 1] x [0.4, 0.6]^2: each takes three vertices
/// consecutive in x order from a pool of count * 3 / 2, so neighbours in x overlap and some
/// share one or two vertices.
Mesh random_soup(int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Mesh m;
  const int pool = std::max(3, count * 3 / 2);
  for (int v = 0; v < pool; ++v) m.x.emplace_back(dyadic(unit(rng)), dyadic(unit(rng)), dyadic(unit(rng)));
  std::vector<int> by_x(static_cast<std::size_t>(pool));
  for (int v = 0; v < pool; ++v) by_x[static_cast<std::size_t>(v)] = v;
  std::sort(by_x.begin(), by_x.end(), [&](int p, int q) { return m.x[p].x() < m.x[q].x() || (m.x[p].x() == m.x[q].x() && p < q); });
  std::uniform_int_distribution<int> start(0, pool - 3);
  for (int t = 0; t < count; ++t) {
    const int s = start(rng);
    const int a = by_x[s], b = by_x[s + 1], c = by_x[s + 2];
    m.tris.push_back({a, b, c});
  }
  for (Vec3& p : m.x) p = Vec3(p.x(), dyadic(0.5 + (p.y() - 0.5) * 0.2), dyadic(0.5 + (p.z() - 0.5) * 0.2));
  return m;
}

/// Every pair i < j sharing no vertex whose closed double-precision boxes meet.
std::set<std::array<int, 2>> brute_pairs(const Mesh& m) {
  const int n = static_cast<int>(m.tris.size());
  std::vector<std::array<double, 6>> box(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) {
      box[i][d] = std::min({m.x[m.tris[i][0]][d], m.x[m.tris[i][1]][d], m.x[m.tris[i][2]][d]});
      box[i][d + 3] = std::max({m.x[m.tris[i][0]][d], m.x[m.tris[i][1]][d], m.x[m.tris[i][2]][d]});
    }
  }
  std::set<std::array<int, 2>> out;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      bool meet = true;
      for (int d = 0; d < 3 && meet; ++d) meet = box[i][d] <= box[j][d + 3] && box[j][d] <= box[i][d + 3];
      if (!meet) continue;
      bool share = false;
      for (int u : m.tris[i])
        for (int v : m.tris[j]) share = share || u == v;
      if (!share) out.insert({i, j});
    }
  }
  return out;
}

/// The overlapping pairs of m at `threads`, from a tree built on m (asked twice, to check
/// that reused buffers give the same answer).
std::vector<std::array<int, 2>> tree_pairs(const Mesh& m, int threads, int* parts) {
  TriangleBvh bvh;
  bvh.build(m.x, m.tris);
  std::vector<std::array<int, 2>> first, second;
  bvh.overlapping_pairs(first, threads);
  bvh.refit(m.x);
  bvh.overlapping_pairs(second, threads);
  EXPECT_EQ(first, second) << threads << " threads, asked twice";
  *parts = bvh.last_parts();
  return first;
}

/// Checks the contract on m: the same list at every thread count, the brute-force set, each
/// pair once with i < j, and the threads used as documented.
void check_mesh(const Mesh& m, const char* name) {
  const std::set<std::array<int, 2>> truth = brute_pairs(m);
  int parts = 0;
  const std::vector<std::array<int, 2>> one = tree_pairs(m, 1, &parts);
  EXPECT_EQ(parts, 1) << name;
  const std::set<std::array<int, 2>> as_set(one.begin(), one.end());
  EXPECT_EQ(as_set, truth) << name;
  EXPECT_EQ(one.size(), truth.size()) << name << ": a pair listed twice";
  for (const auto& p : one) EXPECT_LT(p[0], p[1]) << name;
  for (int threads : {2, 3, 8}) {
    EXPECT_EQ(tree_pairs(m, threads, &parts), one) << name << " at " << threads << " threads";
    const std::size_t expected = std::max<std::size_t>(
        1, std::min<std::size_t>(static_cast<std::size_t>(threads), m.tris.size() / TriangleBvh::kTrianglesPerPart));
    EXPECT_EQ(static_cast<std::size_t>(parts), expected) << name << " at " << threads << " threads";
  }
}

TEST(TriangleBvhThreads, EmptyAndTinyMeshesGiveTheBruteForcePairsAtAnyThreadCount) {
  Mesh empty;
  check_mesh(empty, "no triangles");
  empty.x = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  check_mesh(empty, "vertices, no triangles");
  for (int count : {1, 2, 3, 4, 5, 16, 17, 64}) {
    const Mesh m = random_soup(count, 100 + count);
    check_mesh(m, ("soup of " + std::to_string(count)).c_str());
  }
  // Two triangles: touching at a corner's coordinates without sharing it, and apart.
  Mesh pair;
  pair.x = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 0), Vec3(1, 2, 0)};
  pair.tris = {{0, 1, 2}, {3, 4, 5}};
  check_mesh(pair, "two triangles touching at (1, 1)");
  EXPECT_EQ(brute_pairs(pair).size(), 1u);
  pair.x[3] = Vec3(1.0 + 1.0 / 4096, 1, 0);
  pair.x[5] = Vec3(1.0 + 1.0 / 4096, 2, 0);
  check_mesh(pair, "two triangles 2^-12 apart");
  EXPECT_TRUE(brute_pairs(pair).empty());
}

TEST(TriangleBvhThreads, FoldedClothGivesTheBruteForcePairsAtAnyThreadCount) {
  const Mesh m = folded_cloth(80);  // 12482 triangles: up to 6 threads
  ASSERT_GE(m.tris.size() / TriangleBvh::kTrianglesPerPart, 6u);
  check_mesh(m, "folded 80 x 80 cloth");
  // Folded layers 0.02 apart: pairs beyond the mesh neighbours exist where the ripple crosses.
  EXPECT_GT(brute_pairs(m).size(), m.tris.size());
}

TEST(TriangleBvhThreads, RandomSoupsGiveTheBruteForcePairsAtAnyThreadCount) {
  for (std::uint64_t seed : {1u, 2u}) {
    const Mesh m = random_soup(12000, seed);
    check_mesh(m, ("soup of 12000, seed " + std::to_string(seed)).c_str());
  }
}

TEST(TriangleBvhThreads, MovingPairsAreTheSameAtAnyThreadCount) {
  const Mesh a = folded_cloth(80);
  Mesh b = a;
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> step(-40, 40);
  for (Vec3& p : b.x) p += Vec3(step(rng), step(rng), step(rng)) / 4096.0;
  std::vector<std::array<int, 2>> one, swept;
  {
    TriangleBvh bvh;
    bvh.build(a.x, a.tris);
    bvh.refit(a.x, b.x);
    bvh.moving_pairs(one, 1);
    bvh.overlapping_pairs(swept, 1);
  }
  ASSERT_FALSE(one.empty());
  // A subsequence of the swept-box pairs (triangle_bvh.h: the same order, less some).
  std::size_t k = 0;
  for (const auto& p : swept)
    if (k < one.size() && p == one[k]) ++k;
  EXPECT_EQ(k, one.size()) << "moving pairs are not a subsequence of the swept-box pairs";
  for (int threads : {2, 3, 8}) {
    TriangleBvh bvh;
    bvh.build(a.x, a.tris);
    bvh.refit(a.x, b.x);
    std::vector<std::array<int, 2>> many, many_swept;
    bvh.moving_pairs(many, threads);
    bvh.overlapping_pairs(many_swept, threads);
    EXPECT_GT(bvh.last_parts(), 1) << threads;
    EXPECT_EQ(many, one) << threads << " threads";
    EXPECT_EQ(many_swept, swept) << threads << " threads";
  }
}

}  // namespace
}  // namespace tecido
