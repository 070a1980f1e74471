// FCL adapters against hand-worked cases and the exact referee.
#include "reference/exact_referee.h"
#include "reference/fcl_adapter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace tecido::reference {
namespace {

const Vec3 O(0, 0, 0), X(1, 0, 0), Y(0, 1, 0);
const Triangle T{O, X, Y};
const double tiny = std::ldexp(1.0, -40);

Triangle shifted(Triangle t, const Vec3& d) {
  for (Vec3& v : t) v += d;
  return t;
}

// ---------------------------------------------------------------- triangle-triangle

TEST(FclTriTri, AgreesWithExactOnDyadicTouchingCases) {
  const std::vector<Triangle> others = {
      shifted(T, {0, 0, 1}),                                                // separated
      {Vec3(0.25, 0.25, -1), Vec3(0.25, 0.25, 1), Vec3(2, 2, 0.5)},         // piercing
      {Vec3(0.25, 0.25, 0), Vec3(0.25, 0.5, 1), Vec3(0.5, 0.25, 1)},        // vertex on face
      {Vec3(0.25, 0.25, tiny), Vec3(0.25, 0.5, 1), Vec3(0.5, 0.25, 1)},     // 2^-40 above it
      {O, Vec3(-1, 0, 1), Vec3(0, -1, 1)},                                  // shared vertex
      {O, X, Vec3(0.5, -1, 1)},                                             // shared edge
      {Vec3(0.5, 0, 0), Vec3(0.5, -1, 1), Vec3(0.25, -1, 1)},               // vertex on edge
      {Vec3(0.5, -tiny, 0), Vec3(0.5, -1, 1), Vec3(0.25, -1, 1)},           // 2^-40 off the edge
      {Vec3(0.5, -0.5, 0.5), Vec3(0.5, 0.5, -0.5), Vec3(0.5, -1, -1)},      // skew edges touching
      shifted(T, {0.25, 0.25, 0}),                                          // coplanar overlap
      shifted(T, {1, 1, 0}),                                                // coplanar disjoint
      {X, Vec3(2, 0, 0), Vec3(2, 1, 0)},                                    // coplanar, one vertex
      {X, Y, Vec3(1, 1, 0)},                                                // coplanar, common edge
      {Vec3(0.5 + tiny, 0.5, 0), Vec3(1, 1, 0), Vec3(0.5, 0.5 + tiny, 0)},  // coplanar, 2^-40 apart
  };
  for (std::size_t i = 0; i < others.size(); ++i) {
    const bool truth = exact_tri_tri(T, others[i]);
    EXPECT_EQ(fcl_tri_tri(T, others[i]), truth) << "case " << i;
    EXPECT_EQ(fcl_tri_tri(others[i], T), truth) << "case " << i << " swapped";
  }
}

TEST(FclTriTri, AgreesWithExactOnRandomPairs) {
  std::mt19937_64 rng(42);
  const auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  int wrong = 0;
  for (int i = 0; i < 10000; ++i) {
    Triangle a, b;
    for (Vec3& v : a) v = Vec3(u(), u(), u());
    for (Vec3& v : b) v = Vec3(u(), u(), u());
    wrong += fcl_tri_tri(a, b) != exact_tri_tri(a, b);
  }
  EXPECT_EQ(wrong, 0);
}

TEST(FclTriTri, KnownLimitDegenerateTrianglesInPlane) {
  // A collinear "triangle" (a segment) in T's plane passing outside the corner X. The exact
  // answer is false; FCL's 17 axes lack the segment's in-plane normal, so its SAT finds no
  // separating axis (observed: true). Likewise two disjoint collinear segments. Recorded, not
  // asserted: this is FCL's behaviour on input outside its design (non-degenerate triangles).
  const Triangle segment{Vec3(0.5, -0.5, 0), Vec3(1.5, 0.25, 0), Vec3(1, -0.125, 0)};
  const Triangle s1{O, X, X}, s2{Vec3(0.5, 1, 0), Vec3(0.5, 2, 0), Vec3(0.5, 2, 0)};
  ASSERT_FALSE(exact_tri_tri(T, segment));
  ASSERT_FALSE(exact_tri_tri(s1, s2));
  std::cout << "[ known limit ] fcl segment-in-plane past a corner: " << fcl_tri_tri(T, segment)
            << " (exact 0); two disjoint segments: " << fcl_tri_tri(s1, s2) << " (exact 0)\n";
  RecordProperty("fcl_degenerate_segment_in_plane", fcl_tri_tri(T, segment) ? "true" : "false");
}

// ---------------------------------------------------------------- self-collision

TEST(FclSelfCollision, TwoCrossingQuadsAndAFarOne) {
  // Quad A (faces 0, 1) is the unit square in z = 0, split along y = x: face 0 holds y <= x,
  // face 1 holds y >= x. Quad B (faces 2, 3) is vertical in y = 3/8, x in [1/4, 3/4],
  // z in [-1/2, 1/2], split along its diagonal: at z = 0 face 2 spans x in [1/2, 3/4] and
  // face 3 spans x in [1/4, 1/2]. On the line y = 3/8, z = 0, face 0 covers x >= 3/8 and
  // face 1 x <= 3/8, so the crossing pairs are (0,2), (0,3), (1,3). (0,1) and (2,3) intersect
  // along their shared diagonals but share vertices: filtered. Quad C (4, 5) is far away.
  const std::vector<Vec3> v = {
      {0, 0, 0},           {1, 0, 0},           {1, 1, 0},          {0, 1, 0},           // A
      {0.25, 0.375, -0.5}, {0.75, 0.375, -0.5}, {0.75, 0.375, 0.5}, {0.25, 0.375, 0.5},  // B
      {5, 5, 5},           {6, 5, 5},           {6, 6, 5},          {5, 6, 5},           // C
  };
  const std::vector<std::array<int, 3>> f = {{0, 1, 2}, {0, 2, 3},  {4, 5, 6},
                                             {4, 6, 7}, {8, 9, 10}, {8, 10, 11}};
  const std::vector<std::pair<int, int>> expected = {{0, 2}, {0, 3}, {1, 3}};
  EXPECT_EQ(fcl_self_collision(v, f), expected);

  // The same answer from the exact referee, pair by pair.
  std::vector<std::pair<int, int>> exact;
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) {
      bool shares = false;
      for (int a : f[i])
        for (int b : f[j]) shares = shares || a == b;
      const Triangle ti{v[f[i][0]], v[f[i][1]], v[f[i][2]]}, tj{v[f[j][0]], v[f[j][1]], v[f[j][2]]};
      if (!shares && exact_tri_tri(ti, tj)) exact.emplace_back(i, j);
    }
  EXPECT_EQ(exact, expected);
}

TEST(FclSelfCollision, BvhFindsEveryPairTheLeafTestAccepts) {
  // A random triangle soup with many crossings and shared vertices: the BVH traversal must
  // return exactly the pairs a brute-force loop over fcl_tri_tri finds, minus shared-vertex
  // pairs; and on general-position data that is also the exact answer.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::uniform_int_distribution<int> pick(0, 59);
  std::vector<Vec3> v(60);
  for (Vec3& p : v) p = Vec3(u(rng), u(rng), u(rng));
  std::vector<std::array<int, 3>> f;
  while (f.size() < 80) {
    const std::array<int, 3> t{pick(rng), pick(rng), pick(rng)};
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) f.push_back(t);
  }
  std::vector<std::pair<int, int>> brute, exact;
  int shared_and_intersecting = 0;
  for (int i = 0; i < static_cast<int>(f.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(f.size()); ++j) {
      const Triangle ti{v[f[i][0]], v[f[i][1]], v[f[i][2]]}, tj{v[f[j][0]], v[f[j][1]], v[f[j][2]]};
      bool shares = false;
      for (int a : f[i])
        for (int b : f[j]) shares = shares || a == b;
      if (shares) {
        shared_and_intersecting += fcl_tri_tri(ti, tj);
        continue;
      }
      if (fcl_tri_tri(ti, tj)) brute.emplace_back(i, j);
      if (exact_tri_tri(ti, tj)) exact.emplace_back(i, j);
    }
  ASSERT_GT(brute.size(), 50u);
  ASSERT_GT(shared_and_intersecting, 0);  // the filter has something to remove
  EXPECT_EQ(fcl_self_collision(v, f), brute);
  EXPECT_EQ(brute, exact);
}

TEST(FclSelfCollision, EdgeCasesAndBadInput) {
  EXPECT_TRUE(fcl_self_collision({}, {}).empty());
  EXPECT_TRUE(fcl_self_collision({O, X, Y}, {{0, 1, 2}}).empty());
  EXPECT_THROW(fcl_self_collision({O, X, Y}, {{0, 1, 3}, {0, 1, 2}}), std::invalid_argument);
  EXPECT_THROW(fcl_self_collision({O, X, Y}, {{0, -1, 2}, {0, 1, 2}}), std::invalid_argument);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(fcl_self_collision({O, X, Vec3(nan, 0, 0)}, {{0, 1, 2}, {0, 1, 2}}), std::invalid_argument);
}

// ---------------------------------------------------------------- segment versus plane

BoundedPlane unit_plane() {
  BoundedPlane p;
  p.half_extents = Vec2(1, 0.5);
  return p;
}

/// FCL's t is the time of reaching a slab 2^-42 (relative) thick: within 1e-12 for these
/// head-on segments of length ~1.
void expect_fcl_hit(const BoundedPlane& p, const Vec3& a, const Vec3& b, double t, double tol = 1e-12) {
  const auto r = fcl_segment_plane(p, a, b);
  ASSERT_TRUE(r.has_value());
  EXPECT_TRUE(r->hit);
  EXPECT_NEAR(r->t, t, tol);
  const ExactSegmentPlane e = exact_segment_plane(p, a, b);  // the hand-worked t is the exact one
  EXPECT_TRUE(e.hit);
  EXPECT_EQ(e.t, t);
}

void expect_fcl_miss(const BoundedPlane& p, const Vec3& a, const Vec3& b) {
  const auto r = fcl_segment_plane(p, a, b);
  ASSERT_TRUE(r.has_value());
  EXPECT_FALSE(r->hit);
  EXPECT_FALSE(exact_segment_plane(p, a, b).hit);
}

TEST(FclSegmentPlane, Crossings) {
  const BoundedPlane p = unit_plane();
  expect_fcl_hit(p, {0, 0, 1}, {0, 0, -3}, 0.25);
  expect_fcl_hit(p, {0.25, 0.125, 1}, {0.5, -0.125, -3}, 0.25);
  expect_fcl_hit(p, {1, 0.25, 1}, {1, 0.25, -1}, 0.5);     // on the edge
  expect_fcl_hit(p, {1, 0.5, 1}, {1, 0.5, -1}, 0.5);       // on the corner
  expect_fcl_hit(p, {-1, -0.5, -3}, {-1, -0.5, 1}, 0.75);  // from below, opposite corner
  expect_fcl_hit(p, {0.5, 0.5, 1}, {1.5, 0.5, -1}, 0.5);   // oblique, lands on the corner
  expect_fcl_miss(p, {0, 0, 1}, {0, 0, tiny});
  expect_fcl_miss(p, {-3, 0, 1}, {3, 0, 1});
  expect_fcl_miss(p, {3, 0, 1}, {3, 0, -1});
}

TEST(FclSegmentPlane, EndsAndDegenerateSegments) {
  const BoundedPlane p = unit_plane();
  // FCL's conservative advancement alone misses this (it reports only toc < 1); the adapter's
  // discrete check at the end point catches it.
  expect_fcl_hit(p, {1, 0, 1}, {1, 0, 0}, 1.0);
  expect_fcl_hit(p, {0.5, 0, 0}, {0.5, 0, 1}, 0.0);
  expect_fcl_hit(p, {0.5, 0.25, 0}, {0.5, 0.25, 0}, 0.0);
  expect_fcl_miss(p, {0.5, 0.25, 1}, {0.5, 0.25, 1});
  expect_fcl_miss(p, {3, 0.25, 0}, {3, 0.25, 0});
}

TEST(FclSegmentPlane, SegmentsInThePlane) {
  const BoundedPlane p = unit_plane();
  expect_fcl_hit(p, {-3, 0, 0}, {1, 0, 0}, 0.5);
  expect_fcl_hit(p, {-3, 0.5, 0}, {1, 0.5, 0}, 0.5);  // along the edge
  expect_fcl_hit(p, {-3, 0, 0}, {-1, 0, 0}, 1.0);     // ends on the border
  expect_fcl_hit(p, {0.5, 0, 0}, {3, 0, 0}, 0.0);
  // Oblique entry: conservative advancement converges from below and stops within t_err.
  expect_fcl_hit(p, {-3, -3, 0}, {1, 1, 0}, 0.625, 1e-4);
  expect_fcl_miss(p, {-3, 0.75, 0}, {1, 0.75, 0});
}

TEST(FclSegmentPlane, TiltedPlaneThatANaiveSetUpTunnelsThrough) {
  // With a zero-thickness box posed at this plane in world coordinates, FCL reported a miss:
  // the landing point's closest-point direction was rounding noise (see fcl_adapter.cpp).
  const BoundedPlane p =
      make_bounded_plane(Vec3(0.1, 0.2, 0.3), Vec3(0.3, -0.4, 1.2), Vec3(1, 0.2, 0), Vec2(0.7, 0.3), 0);
  const Vec3 a = p.position + p.normal * 0.5 + p.forward * 0.3,
             b = p.position - p.normal * 0.25 + p.right() * 0.1;
  const ExactSegmentPlane e = exact_segment_plane(p, a, b);
  ASSERT_TRUE(e.hit);
  const auto r = fcl_segment_plane(p, a, b);
  ASSERT_TRUE(r.has_value());
  EXPECT_TRUE(r->hit);
  EXPECT_NEAR(r->t, e.t, 1e-12);
}

TEST(FclSegmentPlane, AgreesWithExactAwayFromTheBorder) {
  // Random planes and segments; cases whose exact crossing is nearer than 1e-3 to the border
  // (relative to the segment's length), or nearly parallel, are left to the known-limit test.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), h(0.1, 1);
  const auto rv = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  int compared = 0, hits = 0, wrong = 0, t_off = 0;
  double worst_t = 0;
  for (int i = 0; i < 5000; ++i) {
    const BoundedPlane p = make_bounded_plane(rv(), rv(), rv(), Vec2(h(rng), h(rng)), 0);
    const Vec3 a = p.position + 2 * rv(), b = p.position + 2 * rv();
    const double s1 = p.side(a), s2 = p.side(b), len = (b - a).norm();
    if (s1 * s2 < 0) {
      const Vec3 c = a + (s1 / (s1 - s2)) * (b - a) - p.position;
      const double margin = std::min(p.half_extents.x() - std::abs(p.forward.dot(c)),
                                     p.half_extents.y() - std::abs(p.right().dot(c)));
      if (std::abs(margin) < 1e-3 * len || std::abs(s1 - s2) < 1e-3 * len) continue;
    }
    const ExactSegmentPlane e = exact_segment_plane(p, a, b);
    const auto r = fcl_segment_plane(p, a, b);
    ASSERT_TRUE(r.has_value());
    ++compared;
    hits += e.hit;
    if (r->hit != e.hit) {
      ++wrong;
    } else if (e.hit) {
      worst_t = std::max(worst_t, std::abs(r->t - e.t));
      t_off += std::abs(r->t - e.t) > 1e-9;
    }
  }
  std::cout << "[ measured ] fcl vs exact: " << compared << " segments, " << hits << " hits, " << wrong
            << " wrong, " << t_off << " with |dt| > 1e-9, worst |dt| " << worst_t << "\n";
  EXPECT_GT(hits, 200);
  EXPECT_EQ(wrong, 0);
  EXPECT_LE(worst_t, 1e-4);  // FCL's conservative advancement stops within t_err = 1e-4
}

TEST(FclSegmentPlane, KnownLimitNearMissesPastTheBorder) {
  // A segment coming from outside the rectangle's shadow and crossing the plane 2^-30 outside
  // the edge x = hx: exact says miss. FCL's conservative advancement creeps towards the edge,
  // stops once its next step is <= t_err = 1e-4 and reports contact (observed: hit). Head-on
  // near misses (from above the rectangle) are answered right. Recorded, not asserted.
  const BoundedPlane p = unit_plane();
  const double off = std::ldexp(1.0, -30);
  const Vec3 a(1.5 + off, 0, 1), b(0.5 + off, 0, -1);
  ASSERT_FALSE(exact_segment_plane(p, a, b).hit);
  const auto r = fcl_segment_plane(p, a, b);
  ASSERT_TRUE(r.has_value());
  std::cout << "[ known limit ] fcl on a 2^-30 near miss past the border: hit=" << r->hit << " t=" << r->t
            << " (exact: miss)\n";
  RecordProperty("fcl_near_miss_2^-30", r->hit ? "hit" : "miss");
}

TEST(FclSegmentPlane, CannotAnswerBadInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(fcl_segment_plane(unit_plane(), {nan, 0, 1}, {0, 0, -1}), std::nullopt);
  BoundedPlane p = unit_plane();
  p.half_extents.y() = -1;
  EXPECT_EQ(fcl_segment_plane(p, {0, 0, 1}, {0, 0, -1}), std::nullopt);
  p = unit_plane();
  p.normal.z() = INFINITY;
  EXPECT_EQ(fcl_segment_plane(p, {0, 0, 1}, {0, 0, -1}), std::nullopt);
}

}  // namespace
}  // namespace tecido::reference
