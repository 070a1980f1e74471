// Continuous self-collision (core/cloth/continuous_self_collision.h): the broad phase (swept
// box tree, one test per primitive pair) must return exactly the brute force over all pairs,
// on random meshes and on recorded cloth frames; on a sheet passing through another within one
// step (both frames intersection-free, so discrete self-collision sees nothing) it must find
// every crossing, worked out independently in 2-D.
#include "core/scene/cloth_builder.h"
#include "core/cloth/continuous_self_collision.h"
#include "core/cloth/self_collision.h"
#include "core/simulation/simulation.h"
#include "core/geometry/ccd/ccd.h"
#include "core/geometry/ccd/batch/stages.h"

#include <gtest/gtest.h>

#include <random>

namespace tecido {
namespace {

struct Mesh {
  std::vector<Vec3> x;
  std::vector<std::array<int, 3>> tris;
};

// An n x n grid of spacing h at height z, shifted by (ox, oy), appended to m.
void append_grid(Mesh& m, int n, double h, double ox, double oy, double z) {
  const int first = static_cast<int>(m.x.size());
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) m.x.emplace_back(ox + c * h, oy + r * h, z);
  for (int r = 0; r + 1 < n; ++r) {
    for (int c = 0; c + 1 < n; ++c) {
      const int a = first + r * n + c, b = a + 1, d = a + n + 1, e = a + n;
      m.tris.push_back({a, b, d});  // the cloth builder's split (cloth_builder.h)
      m.tris.push_back({a, d, e});
    }
  }
}

std::size_t total(const ContinuousContacts& c) { return c.vertex_face.size() + c.edge_edge.size(); }

// Exact 2-D orientation for the dyadic coordinates used below (products are exact).
double orient(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool inside_closed(const Vec3& p, const Mesh& m, const std::array<int, 3>& t) {
  const double o0 = orient(m.x[t[0]], m.x[t[1]], p), o1 = orient(m.x[t[1]], m.x[t[2]], p),
               o2 = orient(m.x[t[2]], m.x[t[0]], p);
  return (o0 >= 0 && o1 >= 0 && o2 >= 0) || (o0 <= 0 && o1 <= 0 && o2 <= 0);
}

bool segments_touch(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double d1 = orient(a, b, c), d2 = orient(a, b, d), d3 = orient(c, d, a), d4 = orient(c, d, b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  auto on = [](const Vec3& p, const Vec3& q, const Vec3& r) {  // r on segment pq, collinear
    return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) && std::min(p.y(), q.y()) <= r.y() &&
           r.y() <= std::max(p.y(), q.y());
  };
  return (d1 == 0 && on(a, b, c)) || (d2 == 0 && on(a, b, d)) || (d3 == 0 && on(c, d, a)) || (d4 == 0 && on(c, d, b));
}

TEST(ContinuousSelfCollision, SheetPassingThroughAnotherWithinOneStep) {
  // Sheet A at z = 0, at rest; sheet B, shifted by (5/16, 3/16) h in the plane, falls from
  // z = +1/16 to -1/16: it lies in A's plane at t = 1/2 and is 1/16 away at both frames.
  // Coordinates are dyadic, so the 2-D truth below is exact: at t = 1/2 a vertex of one sheet
  // touches every face of the other that contains it (in 2-D), two edges touch when their
  // 2-D segments meet; at every other time the sheets are apart.
  const int n = 9;
  const double h = 0.125;
  Mesh m;
  append_grid(m, n, h, 0.0, 0.0, 0.0);
  const int nb = static_cast<int>(m.x.size());
  append_grid(m, n, h, 5.0 / 16 * h, 3.0 / 16 * h, 1.0 / 16);
  std::vector<Vec3> x1 = m.x;
  for (int v = nb; v < static_cast<int>(x1.size()); ++v) x1[v].z() = -1.0 / 16;
  const std::size_t na_tris = m.tris.size() / 2;

  // Discrete self-collision sees nothing at either frame.
  EXPECT_TRUE(self_collision_pairs(m.x, m.tris).empty());
  EXPECT_TRUE(self_collision_pairs(x1, m.tris).empty());

  // The truth in 2-D.
  ContinuousContacts truth;
  for (int v = 0; v < static_cast<int>(m.x.size()); ++v) {
    const bool in_a = v < nb;
    for (std::size_t f = 0; f < m.tris.size(); ++f) {
      if ((f < na_tris) == in_a) continue;  // same sheet: apart at all times (flat, no self-contact)
      if (inside_closed(m.x[v], m, m.tris[f])) truth.vertex_face.push_back({v, static_cast<int>(f)});
    }
  }
  std::vector<MeshEdge> edges;
  for (const auto& t : m.tris)
    for (int k = 0; k < 3; ++k) edges.push_back({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const MeshEdge& e : edges)
    for (const MeshEdge& g : edges)
      if (e < g && (e[0] < nb) != (g[0] < nb) && segments_touch(m.x[e[0]], m.x[e[1]], m.x[g[0]], m.x[g[1]]))
        truth.edge_edge.push_back({e, g});
  std::sort(truth.vertex_face.begin(), truth.vertex_face.end());
  std::sort(truth.edge_edge.begin(), truth.edge_edge.end());
  ASSERT_GT(truth.vertex_face.size(), 100u);
  ASSERT_GT(truth.edge_edge.size(), 300u);

  ContinuousSelfCollisionDetector det(m.tris, m.x);
  const ContinuousContacts& fast = det.detect(m.x, x1);
  EXPECT_EQ(fast.vertex_face, truth.vertex_face);
  EXPECT_EQ(fast.edge_edge, truth.edge_edge);
  EXPECT_EQ(continuous_self_collision_brute(m.x, x1, m.tris), truth);
}

TEST(ContinuousSelfCollision, BroadPhaseMatchesBruteForceOnRandomMeshes) {
  // Grids whose vertices are jittered and moved at random by about an edge length: folds,
  // crossings and near misses everywhere.
  std::mt19937_64 rng(4711);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::size_t found = 0;
  for (int trial = 0; trial < 6; ++trial) {
    Mesh m;
    append_grid(m, 7, 0.1, 0.0, 0.0, 0.0);
    for (Vec3& p : m.x) p += 0.03 * Vec3(u(rng), u(rng), u(rng));
    std::vector<Vec3> x1 = m.x;
    const double step = 0.05 * (trial + 1);
    for (Vec3& p : x1) p += step * Vec3(u(rng), u(rng), u(rng));
    ContinuousSelfCollisionDetector det(m.tris, m.x);
    const ContinuousContacts fast = det.detect(m.x, x1);
    EXPECT_EQ(fast, continuous_self_collision_brute(m.x, x1, m.tris)) << "trial " << trial;
    found += total(fast);
  }
  EXPECT_GT(found, 50u);  // the meshes must exercise the test
}

// The vector widths of the batched first stages this CPU runs (the output must not depend on it).
std::vector<int> widths() {
  std::vector<int> w;
  for (int k : {1, 2, 4, 8})
    if (ccd_batch_width_available(k)) w.push_back(k);
  return w;
}

TEST(ContinuousSelfCollision, BroadPhaseMatchesBruteForceAtEveryWidthAndScale) {
  // Jittered grids moved at random, scaled by 1e-30 .. 1e30 and moved far off: the batched
  // stages decide the cubic only where ccd would not rescale, and must agree everywhere.
  std::mt19937_64 rng(31337);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mesh m;
  append_grid(m, 7, 0.1, 0.0, 0.0, 0.0);
  for (Vec3& p : m.x) p += 0.03 * Vec3(u(rng), u(rng), u(rng));
  std::vector<Vec3> x1 = m.x;
  for (Vec3& p : x1) p += 0.12 * Vec3(u(rng), u(rng), u(rng));
  std::size_t found = 0;
  for (double scale : {1e-30, 1e-10, 1.0, 1e10, 1e30}) {
    for (const Vec3& shift : {Vec3(0, 0, 0), Vec3(3e3, -1e3, 5e2)}) {
      std::vector<Vec3> a = m.x, b = x1;
      for (Vec3& p : a) p = scale * (p + shift);
      for (Vec3& p : b) p = scale * (p + shift);
      const ContinuousContacts brute = continuous_self_collision_brute(a, b, m.tris);
      found += total(brute);
      for (int w : widths()) {
        ContinuousSelfCollisionDetector det(m.tris, a);
        det.set_simd_width(w);
        EXPECT_EQ(det.detect(a, b), brute) << "scale " << scale << " width " << w;
      }
    }
  }
  EXPECT_GT(found, 100u);
}

TEST(ContinuousSelfCollision, BroadPhaseMatchesBruteForceOnDegenerateMotion) {
  // Motions where the cubic vanishes or the boxes touch exactly: no motion at all, a flat
  // sheet sliding in its own plane (coplanar at all times), a pure translation, triangles
  // collapsing onto a point, and a sheet folded onto itself exactly.
  std::mt19937_64 rng(2718);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mesh m;
  append_grid(m, 6, 0.125, 0.0, 0.0, 0.0);
  std::vector<std::pair<std::vector<Vec3>, std::vector<Vec3>>> motions;
  std::vector<Vec3> crumpled = m.x;
  for (Vec3& p : crumpled) p += 0.1 * Vec3(u(rng), u(rng), u(rng));
  motions.push_back({crumpled, crumpled});  // still
  std::vector<Vec3> slid = m.x;
  for (Vec3& p : slid) p += 0.1 * Vec3(u(rng), u(rng), 0.0);
  motions.push_back({m.x, slid});  // coplanar throughout
  std::vector<Vec3> moved = crumpled;
  for (Vec3& p : moved) p += Vec3(0.25, -0.5, 0.125);
  motions.push_back({crumpled, moved});  // translation
  std::vector<Vec3> collapsed(m.x.size(), Vec3(0.3125, 0.3125, 0.0));
  motions.push_back({m.x, collapsed});  // everything onto one point at t = 1
  std::vector<Vec3> folded = m.x;
  for (Vec3& p : folded)
    if (p.x() > 0.3125) p.x() = 0.625 - p.x();  // mirrored onto the other half, exactly
  motions.push_back({m.x, folded});
  for (std::size_t k = 0; k < motions.size(); ++k) {
    const auto& [a, b] = motions[k];
    const ContinuousContacts brute = continuous_self_collision_brute(a, b, m.tris);
    for (int w : widths()) {
      ContinuousSelfCollisionDetector det(m.tris, m.x);
      det.set_simd_width(w);
      EXPECT_EQ(det.detect(a, b), brute) << "motion " << k << " width " << w;
    }
  }
}

TEST(ContinuousSelfCollision, BroadPhaseMatchesBruteForceOnTriangleSoups) {
  // Separate triangles (no shared index) and a few fans sharing vertices, random motions.
  std::mt19937_64 rng(90210);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 4; ++trial) {
    Mesh m;
    for (int t = 0; t < 60; ++t) {
      const Vec3 c(u(rng), u(rng), u(rng));
      const int k = static_cast<int>(m.x.size());
      for (int i = 0; i < 3; ++i) m.x.push_back(c + 0.15 * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
      m.tris.push_back({k, k + 1, k + 2});
      if (t % 3 == 0) {  // a neighbour sharing the edge (k, k + 2)
        m.x.push_back(c + 0.15 * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
        m.tris.push_back({k, k + 2, k + 3});
      }
    }
    std::vector<Vec3> x1 = m.x;
    for (Vec3& p : x1) p += 0.2 * Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
    EXPECT_EQ(continuous_self_collision(m.x, x1, m.tris), continuous_self_collision_brute(m.x, x1, m.tris));
  }
}

TEST(ContinuousSelfCollision, BroadPhaseMatchesBruteForceOnRecordedClothSteps) {
  // A 12 x 12 curtain on three hooks in a circling wind, no self-collision response: it
  // folds through itself. Consecutive frames (the motion of one step) every 25 steps.
  Scene s;
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
  spec.rows = spec.cols = 12;
  spec.spacing = 0.1;
  spec.origin = Vec3(0, 1.1, -0.55);
  spec.axis_u = Vec3::UnitZ();
  spec.axis_v = -Vec3::UnitY();
  spec.total_mass = 12 * 12 * 0.01;
  spec.stiffness_b = spec.stiffness_a = 4.0;
  spec.pins = {{0, 0}, {0, 6}, {0, 11}};
  append_cloth(s, spec);
  Simulation sim(s);
  ContinuousSelfCollisionDetector det(s.triangles, s.particles.x);
  std::size_t found = 0;
  for (int k = 1; k <= 500; ++k) {
    const std::vector<Vec3> before = sim.particles().x;
    sim.step();
    if (k % 25 != 0) continue;
    const std::vector<Vec3>& after = sim.particles().x;
    const ContinuousContacts fast = det.detect(before, after);
    EXPECT_EQ(fast, continuous_self_collision_brute(before, after, s.triangles)) << "step " << k;
    found += total(fast);
  }
  EXPECT_GT(found, 0u);
}

TEST(ContinuousSelfCollision, SameAnswerAtEveryThreadCount) {
  // A 40 x 40 jittered grid moved at random by about an edge length: tens of thousands of tree
  // pairs, enough for several shares. Every thread count gives the one-thread answer and test
  // count; the one-thread answer is checked against the brute force on a 16 x 16 corner of the
  // same motion (the brute force of the full mesh is too slow for a unit test), and the
  // threaded runs must actually have run in shares.
  std::mt19937_64 rng(2027);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n : {16, 40}) {
    Mesh m;
    append_grid(m, n, 0.05, 0.0, 0.0, 0.0);
    for (Vec3& p : m.x) p += 0.015 * Vec3(u(rng), u(rng), u(rng));
    std::vector<Vec3> x1 = m.x;
    for (Vec3& p : x1) p += 0.06 * Vec3(u(rng), u(rng), u(rng));
    ContinuousSelfCollisionDetector one(m.tris, m.x);
    const ContinuousContacts expected = one.detect(m.x, x1);
    ASSERT_GT(total(expected), 100u);
    if (n == 16) {
      EXPECT_EQ(expected, continuous_self_collision_brute(m.x, x1, m.tris));
    }
    for (int threads : {2, 3, 8}) {
      ContinuousSelfCollisionDetector det(m.tris, m.x);
      det.set_threads(threads);
      for (int round = 0; round < 2; ++round) {  // the workers' buffers are reused
        EXPECT_EQ(det.detect(m.x, x1), expected) << "n " << n << " threads " << threads << " round " << round;
        EXPECT_EQ(det.last_tests(), one.last_tests());
      }
      if (n == 40) {
        EXPECT_GT(det.last_parts(), 1) << "threads " << threads;
      }
    }
    // Confirmation in shares keeps the order and the pairs.
    const auto keep = [](const CcdQuery& q) { return (q.x0[0].x() + q.x1[1].y()) > 0.6; };
    const ContinuousContacts filtered = filter_contacts(expected, m.x, x1, m.tris, keep);
    EXPECT_LT(total(filtered), total(expected));
    for (int threads : {2, 5}) EXPECT_EQ(filter_contacts(expected, m.x, x1, m.tris, keep, threads), filtered);
  }
}

TEST(ContinuousSelfCollision, EveryReportedPairIsAValidFeaturePairOnce) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mesh m;
  append_grid(m, 8, 0.1, 0.0, 0.0, 0.0);
  std::vector<Vec3> x1 = m.x;
  for (Vec3& p : x1) p += 0.15 * Vec3(u(rng), u(rng), u(rng));
  const ContinuousContacts c = continuous_self_collision(m.x, x1, m.tris);
  ASSERT_GT(total(c), 0u);
  for (const auto& vf : c.vertex_face) {
    const auto& t = m.tris[vf[1]];
    EXPECT_TRUE(vf[0] != t[0] && vf[0] != t[1] && vf[0] != t[2]);
  }
  for (const auto& ee : c.edge_edge) {
    EXPECT_LT(ee[0][0], ee[0][1]);
    EXPECT_LT(ee[1][0], ee[1][1]);
    EXPECT_LT(ee[0], ee[1]);
    EXPECT_TRUE(ee[0][0] != ee[1][0] && ee[0][0] != ee[1][1] && ee[0][1] != ee[1][0] && ee[0][1] != ee[1][1]);
  }
  EXPECT_TRUE(std::is_sorted(c.vertex_face.begin(), c.vertex_face.end()));
  EXPECT_TRUE(std::adjacent_find(c.vertex_face.begin(), c.vertex_face.end()) == c.vertex_face.end());
  EXPECT_TRUE(std::is_sorted(c.edge_edge.begin(), c.edge_edge.end()));
  EXPECT_TRUE(std::adjacent_find(c.edge_edge.begin(), c.edge_edge.end()) == c.edge_edge.end());
}

TEST(ContinuousSelfCollision, FilterKeepsWhatThePredicateConfirms) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mesh m;
  append_grid(m, 8, 0.1, 0.0, 0.0, 0.0);
  std::vector<Vec3> x1 = m.x;
  for (Vec3& p : x1) p += 0.15 * Vec3(u(rng), u(rng), u(rng));
  const ContinuousContacts c = continuous_self_collision(m.x, x1, m.tris);
  ASSERT_GT(c.edge_edge.size(), 0u);
  ASSERT_GT(c.vertex_face.size(), 0u);
  // The predicate sees exactly the queries the test saw: confirming with the same test keeps all.
  EXPECT_EQ(filter_contacts(c, m.x, x1, m.tris, [](const CcdQuery& q) { return ccd(q).hit; }), c);
  // Only edge-edge queries confirmed.
  const ContinuousContacts ee =
      filter_contacts(c, m.x, x1, m.tris, [](const CcdQuery& q) { return q.kind == CcdKind::EdgeEdge; });
  EXPECT_TRUE(ee.vertex_face.empty());
  EXPECT_EQ(ee.edge_edge, c.edge_edge);
  // The query handed over is the pair's: vertex first, then the face's corners in order.
  const auto vf = c.vertex_face.front();
  const CcdQuery q = vertex_face_query(m.x, x1, vf[0], m.tris[vf[1]]);
  EXPECT_EQ(q.x0[0], m.x[vf[0]]);
  EXPECT_EQ(q.x1[3], x1[m.tris[vf[1]][2]]);
}

TEST(ContinuousSelfCollision, CustomTestIsUsed) {
  // A test that says "hit" for everything: every feature pair whose swept boxes overlap
  // (broad phase) or every pair at all (brute force, which does not filter by boxes), so
  // only compare against a direct count on a tiny mesh where all boxes overlap.
  Mesh m;
  append_grid(m, 3, 0.1, 0.0, 0.0, 0.0);
  std::vector<Vec3> x1 = m.x;
  for (Vec3& p : x1) p *= -1.0;  // mirrored through the origin: every swept box spans it
  auto always = [](const CcdQuery&) { return CcdAnswer{true, 0.0}; };
  const ContinuousContacts all = continuous_self_collision_brute(m.x, x1, m.tris, always);
  EXPECT_EQ(continuous_self_collision(m.x, x1, m.tris, always), all);
  // 3 x 3 grid: 9 vertices, 8 faces, 16 edges. Vertex-face pairs: sum over faces of
  // (9 - 3) = 48. Edge-edge pairs sharing no vertex: counted directly.
  EXPECT_EQ(all.vertex_face.size(), 48u);
}

}  // namespace
}  // namespace tecido
