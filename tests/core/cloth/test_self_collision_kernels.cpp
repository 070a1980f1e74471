// The run-time chosen SIMD paths of self-collision must not change any answer:
//  - TriangleBvh's 16-lane AVX-512 node/leaf masks against the SSE2 path (same pair list, in
//    the same order);
//  - tri_tri_reject8 (batched first plane test): a set bit must mean tri_tri_intersect is
//    false, on random, touching, coplanar and scaled triangle pairs.
// On a CPU without AVX-512F both checks reduce to the portable path and pass trivially.
#include "core/cloth/triangle_bvh.h"
#include "core/geometry/tri_tri_intersect.h"
#include "core/scene/cloth_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tecido {
namespace {

std::vector<Vec3> rippled_fold(const std::vector<Vec3>& rest) {
  std::vector<Vec3> x = rest;
  for (auto& p : x) {
    const double u = p.x(), v = p.y();
    const double r = 0.03 * std::sin(9.0 * u + 1.0) * std::sin(7.0 * v);
    p = u <= 0.5 ? Vec3(u, v, r) : Vec3(1.0 - u, v, 0.02 - r);
  }
  return x;
}

TEST(SelfCollisionKernels, WideBvhMasksGiveTheSamePairList) {
  for (int n : {2, 3, 9, 40}) {
    Scene s;
    append_cloth(s, unit_square_cloth(n));
    const std::vector<Vec3> rest = s.particles.x;
    for (const auto& x : {rest, rippled_fold(rest)}) {
      TriangleBvh wide, narrow;
      wide.build(rest, s.triangles);
      narrow.build(rest, s.triangles);
      narrow.set_use_wide_kernel(false);
      wide.refit(x);
      narrow.refit(x);
      std::vector<std::array<int, 2>> a, b;
      wide.overlapping_pairs(a);
      narrow.overlapping_pairs(b);
      EXPECT_EQ(a, b) << "n = " << n;
    }
  }
}

TEST(SelfCollisionKernels, Reject8OnlyRejectsDisjointPairs) {
  if (!tri_tri_reject8_available()) GTEST_SKIP() << "no AVX-512F on this CPU";
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 5);
  int rejected = 0;
  for (int round = 0; round < 4000; ++round) {
    const double scale = std::ldexp(1.0, std::uniform_int_distribution<int>(-300, 300)(rng));
    // Eight pairs (p_k, q_k): vertices 6k .. 6k + 5 in x.
    std::vector<Vec3> x(48);
    for (int k = 0; k < 8; ++k) {
      for (int i = 0; i < 6; ++i) x[6 * k + i] = scale * Vec3(U(rng), U(rng), U(rng));
      const int kind = pick(rng);
      if (kind == 1) x[6 * k + 3] = x[6 * k + 0];  // touching at a vertex
      if (kind == 2) {                               // coplanar: all on z = c
        for (int i = 0; i < 6; ++i) x[6 * k + i].z() = scale * 0.25;
      }
      if (kind == 3) {  // q's corners near p's plane, a small offset
        for (int i = 3; i < 6; ++i) x[6 * k + i].z() = x[6 * k + 0].z() + scale * 1e-12 * U(rng);
        for (int i = 0; i < 3; ++i) x[6 * k + i].z() = x[6 * k + 0].z();
      }
      if (kind == 4) x[6 * k + 5] = x[6 * k + 4];  // degenerate q
    }
    int pv[3][8], qv[3][8];
    for (int k = 0; k < 8; ++k)
      for (int i = 0; i < 3; ++i) {
        pv[i][k] = 3 * (6 * k + i);
        qv[i][k] = 3 * (6 * k + 3 + i);
      }
    const unsigned bits = tri_tri_reject8(x.data()->data(), pv, qv);
    for (int k = 0; k < 8; ++k) {
      const Triangle p{x[6 * k], x[6 * k + 1], x[6 * k + 2]};
      const Triangle q{x[6 * k + 3], x[6 * k + 4], x[6 * k + 5]};
      if ((bits >> k) & 1u) {
        ++rejected;
        EXPECT_FALSE(tri_tri_intersect(p, q)) << "round " << round << " lane " << k;
        EXPECT_FALSE(tri_tri_intersect(q, p)) << "round " << round << " lane " << k;
      }
    }
  }
  EXPECT_GT(rejected, 1000);  // the filter does reject
}

}  // namespace
}  // namespace tecido
