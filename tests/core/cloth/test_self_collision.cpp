// Self-collision detection: the broad phase (refitted box tree) plus narrow phase must return
// exactly the brute-force pair set, on frames recorded from a cloth crumpling in a circling
// wind (tree built on the rest shape, then refitted) and on seeded random triangle soups,
// including touching and coplanar configurations.
#include "core/cloth/self_collision.h"
#include "core/scene/cloth_builder.h"
#include "core/simulation/self_collision_response.h"
#include "core/simulation/simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tecido {
namespace {

// A 14 x 14 curtain on four hooks in a strong circling wind, no self-collision response: it
// folds through itself from about step 200 on. Returns the positions every `every` of 600 steps.
std::vector<std::vector<Vec3>> record_wind_cloth(Scene& s, int every) {
  s.dt = 0.005;
  s.forces.gravity = Vec3(0, -9.81, 0);
  s.forces.air_drag = 0.01;
  Wind w;
  w.force = Vec3(0.12, 0, 0);
  w.swirl = true;
  w.axis = Vec3::UnitY();
  w.rate = 1.3;
  s.forces.wind = w;
  ClothGridSpec spec;
  spec.rows = spec.cols = 14;
  spec.spacing = 0.1;
  spec.origin = Vec3(0, 1.3, -0.65);
  spec.axis_u = Vec3::UnitZ();
  spec.axis_v = -Vec3::UnitY();
  spec.total_mass = 14 * 14 * 0.01;
  spec.stiffness_b = spec.stiffness_a = 4.0;
  spec.pins = {{0, 0}, {0, 4}, {0, 9}, {0, 13}};
  append_cloth(s, spec);
  Simulation sim(s);
  std::vector<std::vector<Vec3>> frames;
  for (int k = 1; k <= 600; ++k) {
    sim.step();
    if (k % every == 0) frames.push_back(sim.particles().x);
  }
  return frames;
}

TEST(SelfCollision, BroadPhaseMatchesBruteForceOnRecordedClothFrames) {
  Scene s;
  const auto frames = record_wind_cloth(s, 30);
  SelfCollisionDetector det(s.triangles, s.particles.x);  // tree built on the rest shape
  std::size_t total = 0, frames_with_contact = 0;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const auto brute = self_collision_pairs_brute(frames[f], s.triangles);
    const auto fast = det.detect(frames[f]);
    EXPECT_EQ(fast, brute) << "frame " << f;
    total += brute.size();
    frames_with_contact += !brute.empty();
  }
  // The recording must exercise the detector: several frames with real intersections.
  EXPECT_GE(frames_with_contact, 3u);
  EXPECT_GE(total, 20u);
}

Vec3 random_point(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  return Vec3(u(rng), u(rng), u(rng));
}

TEST(SelfCollision, BroadPhaseMatchesBruteForceOnRandomSoups) {
  std::mt19937_64 rng(20141);
  std::uniform_real_distribution<double> size(0.02, 0.25);
  for (int trial = 0; trial < 8; ++trial) {
    // Separate triangles (no shared index), sizes 0.02 to 0.25 in a unit cube.
    std::vector<Vec3> x;
    std::vector<std::array<int, 3>> tris;
    for (int t = 0; t < 250; ++t) {
      const Vec3 c = random_point(rng, 0, 1);
      const double r = size(rng);
      for (int k = 0; k < 3; ++k) x.push_back(c + random_point(rng, -r, r));
      tris.push_back({3 * t, 3 * t + 1, 3 * t + 2});
    }
    // Some triangles over a shared vertex pool (pairs sharing an index are excluded).
    const int pool = static_cast<int>(x.size());
    std::uniform_int_distribution<int> pick(0, pool - 1);
    for (int t = 0; t < 60; ++t) {
      const int a = pick(rng);
      int b = pick(rng), c = pick(rng);
      if (b == a || c == a || c == b) continue;
      tris.push_back({a, b, c});
    }
    // Build on other positions than the query: the tree is only refitted.
    std::vector<Vec3> x_build = x;
    for (auto& p : x_build) p = random_point(rng, 0, 1);
    SelfCollisionDetector det(tris, x_build);
    const auto brute = self_collision_pairs_brute(x, tris);
    EXPECT_EQ(det.detect(x), brute) << "trial " << trial;
    EXPECT_GT(brute.size(), 0u);
  }
}

// Touching and coplanar configurations, where a box test that rounds inward would lose pairs:
// triangles of a flat grid duplicated with fresh indices (every copy touches or overlaps its
// original, coplanar), plus copies shifted to touch only along an edge or at a vertex.
TEST(SelfCollision, SameAnswerAtEveryThreadCount) {
  // A 40 x 40 grid jittered in its plane by more than its spacing (0.06 against 0.05) and a
  // little across it: neighbouring triangles cross everywhere, more than two shares' worth of
  // candidates (a share per 4096; a 0.03 jitter gave fewer than 4096, one share). Every thread count gives the brute force's pairs, and
  // the threaded runs must have run in shares.
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 40;
  std::vector<Vec3> x;
  std::vector<std::array<int, 3>> tris;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) x.push_back(Vec3(0.05 * c, 0.05 * r, 0.0) + Vec3(0.06 * u(rng), 0.06 * u(rng), 0.01 * u(rng)));
  for (int r = 0; r + 1 < n; ++r)
    for (int c = 0; c + 1 < n; ++c) {
      const int a = r * n + c;
      tris.push_back({a, a + 1, a + n + 1});
      tris.push_back({a, a + n + 1, a + n});
    }
  const std::vector<TrianglePair> brute = self_collision_pairs_brute(x, tris);
  ASSERT_GT(brute.size(), 50u);
  for (int threads : {1, 2, 3, 8}) {
    SelfCollisionDetector det(tris, x);
    det.set_threads(threads);
    for (int round = 0; round < 2; ++round) EXPECT_EQ(det.detect(x), brute) << "threads " << threads;
    EXPECT_GE(det.last_candidates(), 2u * 4096u);
    if (threads > 1) {
      EXPECT_GT(det.last_parts(), 1) << "threads " << threads;
    }
  }
}

TEST(SelfCollision, TouchingAndCoplanarPairsAreKept) {
  Scene s;
  ClothGridSpec spec;
  spec.rows = 5;
  spec.cols = 6;
  spec.spacing = 0.1;  // not a power of two: coordinates are rounded
  spec.origin = Vec3(0.3, -0.7, 0.1);
  spec.total_mass = 1;
  spec.stiffness_b = 1;
  append_cloth(s, spec);
  std::vector<Vec3> x = s.particles.x;
  std::vector<std::array<int, 3>> tris = s.triangles;
  const int n = static_cast<int>(x.size());
  for (int i = 0; i < n; ++i) x.push_back(x[i]);  // exact copies
  for (const auto& t : s.triangles) tris.push_back({t[0] + n, t[1] + n, t[2] + n});
  const auto brute = self_collision_pairs_brute(x, tris);
  SelfCollisionDetector det(tris, x);
  EXPECT_EQ(det.detect(x), brute);
  // Every original triangle touches its copy.
  const int nt = static_cast<int>(s.triangles.size());
  for (int t = 0; t < nt; ++t)
    EXPECT_TRUE(std::binary_search(brute.begin(), brute.end(), TrianglePair{t, t + nt})) << t;
  // The flat grid alone has no self-intersection (neighbours share vertices; the rest is apart).
  EXPECT_TRUE(self_collision_pairs(s.particles.x, s.triangles).empty());
}

// Boxes that meet only on a plane (the grid-aligned cloth's neighbours): the narrow phase skips
// the exact test where the two triangles' faces on that plane have boxes apart, and must keep
// every pair that touches there. Worked cases in z = 0 and on a plane x = 1 of a standing pair;
// p = (0,0)-(1,0)-(0,1) has its largest x, 1, at the corner (1, 0) alone.
TEST(SelfCollision, PairsWhoseBoxesOnlyTouchAreDecidedExactly) {
  const std::vector<Vec3> x = {
      {0, 0, 0}, {1, 0, 0}, {0, 1, 0},          // 0-2  p
      {1, 0, 0}, {2, 0, 0}, {2, 1, 0},          // 3-5  a copy of p's corner (1,0): touches p there
      {1, -0.5, 0}, {1, 0.5, 0}, {2, 0, 0},     // 6-8  an edge on x = 1 through (1,0): a T-junction
      {1, 0.5, 0}, {1, 1.5, 0}, {2, 1, 0},      // 9-11 an edge on x = 1 from y 0.5: boxes touch, apart
      {1, std::nextafter(0.0, 1.0), 0}, {2, 0.5, 0}, {2, -0.5, 0},  // 12-14 a corner one ulp above (1,0)
      {1, 0, 1}, {1, 0, 2}, {1, 1, 1},          // 15-17 standing on x = 1 above p's corner: apart in z
      {1, 0, 0.0}, {1, -1, 1}, {1, 1, 1},       // 18-20 standing on x = 1 with a corner on (1,0,0)
  };
  const std::vector<std::array<int, 3>> tris = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}, {12, 13, 14},
                                                {15, 16, 17}, {18, 19, 20}};
  const auto brute = self_collision_pairs_brute(x, tris);
  SelfCollisionDetector det(tris, x);
  EXPECT_EQ(det.detect(x), brute);
  for (const TrianglePair& want : {TrianglePair{0, 1}, TrianglePair{0, 2}, TrianglePair{0, 6}})
    EXPECT_TRUE(std::binary_search(brute.begin(), brute.end(), want)) << want[0] << " " << want[1];
  for (const TrianglePair& apart : {TrianglePair{0, 3}, TrianglePair{0, 4}, TrianglePair{0, 5}})
    EXPECT_FALSE(std::binary_search(brute.begin(), brute.end(), apart)) << apart[0] << " " << apart[1];
  // A flat, grid-aligned cloth on dyadic coordinates (every neighbour box meets another on a
  // side or a corner): no pair, as brute force says.
  Scene s;
  ClothGridSpec spec;
  spec.rows = spec.cols = 17;
  spec.spacing = 0.125;
  spec.total_mass = 1;
  append_cloth(s, spec);
  SelfCollisionDetector flat(s.triangles, s.particles.x);
  EXPECT_EQ(flat.detect(s.particles.x), self_collision_pairs_brute(s.particles.x, s.triangles));
  EXPECT_TRUE(flat.detect(s.particles.x).empty());
  EXPECT_GT(flat.last_candidates(), 1000u);
}

// Tree shapes and coordinate ranges at the edges: meshes of 0 to 40 triangles (a lone leaf,
// part-filled leaves and nodes), and soups scaled from 1e-300 (far below the float range: boxes
// round out to +-FLT_MIN) to 1e300 (far above it: boxes clamp to +-FLT_MAX and beyond), mixed
// with exact zeros. The float boxes must stay conservative, so the result is still brute force's.
TEST(SelfCollision, BroadPhaseMatchesBruteForceAtEveryMeshSizeAndScale) {
  std::mt19937_64 rng(7);
  for (double scale : {1e-300, 1e-40, 1.0, 3e38, 1e300}) {
    for (int count = 0; count <= 40; ++count) {
      std::vector<Vec3> x;
      std::vector<std::array<int, 3>> tris;
      for (int t = 0; t < count; ++t) {
        const Vec3 c = random_point(rng, -1, 1);
        for (int k = 0; k < 3; ++k) {
          Vec3 p = (c + random_point(rng, -0.6, 0.6)) * scale;
          if (t % 5 == 0) p.z() = 0.0;  // some on the plane z = 0 exactly: coplanar, touching
          x.push_back(p);
        }
        tris.push_back({3 * t, 3 * t + 1, 3 * t + 2});
      }
      SelfCollisionDetector det(tris, x);
      EXPECT_EQ(det.detect(x), self_collision_pairs_brute(x, tris)) << "scale " << scale << ", " << count << " triangles";
    }
  }
}

// The responder counts checks and contact checks and detects every `every` steps.
TEST(SelfCollision, ResponderCountsFramesWithContact) {
  Scene s;
  const auto frames = record_wind_cloth(s, 600);  // builds the scene; one frame
  s.self_collision = SelfCollisionSettings{};
  s.self_collision->every = 4;
  Simulation sim(s);
  const auto r = install_self_collision(sim);
  ASSERT_TRUE(r);
  long long contact = 0;
  for (int k = 1; k <= 600; ++k) {
    sim.step();
    if (k % 4 == 0) contact += !r->last_pairs().empty();
  }
  EXPECT_EQ(r->stats().checks, 150);
  EXPECT_EQ(r->stats().contact_checks, contact);
  EXPECT_GT(contact, 0);
  // Same final state as the recording without the hook (response none changes nothing).
  EXPECT_EQ(sim.particles().x, frames.back());
}

}  // namespace
}  // namespace tecido
