// Bullet's classic soft body (reference/bullet_softbody.h): numbering, what it models differently,
// planes, the self-collision option, and the guarded fixed-time run on the tradeoff suite's curtain.
// (Its kLST calibration is tested in test_klst_calibration.cpp.)
#include "reference/bullet_softbody.h"

#include "core/scene/cloth_builder.h"
#include "core/simulation/simulation.h"
#include "tests/support/curtain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <thread>

namespace tecido::reference {
namespace {

const Vec3 kGravity(0, 0, -9.81);

TEST(BulletClassic, NodesAreCoreParticlesInOrder) {
  Scene s = testing::stretch_curtain(5, 100.0, 1e-3);
  s.particles.x[5] += Vec3(0.001, 0.002, -0.003);  // break the grid's regularity (row 1, col 0)
  ClassicSoftBodyOptions o;
  o.klst = 0.005;  // soft enough that every free node visibly sags
  o.kdp = 0.05;
  ClassicSoftBody sb(s, o);
  const auto x = sb.positions();
  ASSERT_EQ(x.size(), s.particles.size());
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(x[i], s.particles.x[i]) << "node " << i;
  for (int k = 0; k < 500; ++k) ASSERT_TRUE(sb.step());
  const auto y = sb.positions();
  for (int col = 0; col < 5; ++col) EXPECT_EQ(y[col], s.particles.x[col]) << "pinned node " << col << " moved";
  // Lower rows sag more: node order follows rows (a renumbering would break this).
  for (int row = 2; row < 5; ++row) {
    const double drop_here = s.particles.x[row * 5 + 2].z() - y[row * 5 + 2].z();
    const double drop_above = s.particles.x[(row - 1) * 5 + 2].z() - y[(row - 1) * 5 + 2].z();
    EXPECT_GT(drop_here, drop_above) << "row " << row;
    EXPECT_GT(drop_above, 0.0) << "row " << row - 1;
  }
}

TEST(BulletClassic, ReportsWhatItModelsDifferently) {
  Scene s = testing::stretch_curtain(4, 100.0, 1e-3);
  s.forces.air_drag = 0.01;
  s.forces.springs[0].damping = 0.1;
  ClassicSoftBody sb(s);
  const auto notes = sb.not_modelled();
  auto has = [&](const std::string& prefix) {
    for (const auto& n : notes)
      if (n.rfind(prefix, 0) == 0) return true;
    return false;
  };
  EXPECT_TRUE(has("Hooke springs"));
  EXPECT_TRUE(has("air_drag"));
  EXPECT_TRUE(has("spring damping"));
  EXPECT_FALSE(has("wind"));
  EXPECT_FALSE(has("self-collision"));
}

// A bounded plane becomes a static box behind it; a falling patch stops on it near the margin.
TEST(BulletClassic, PlaneStopsAFallingPatch) {
  Scene s;
  s.dt = 1.0 / 240.0;
  s.forces.gravity = kGravity;
  ClothGridSpec c;
  c.rows = 3;
  c.cols = 3;
  c.spacing = 0.1;
  c.origin = Vec3(-0.1, -0.1, 0.1);
  c.total_mass = 0.1;
  c.stiffness_b = 50.0;
  append_cloth(s, c);
  s.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(0.5, 0.5), 0.5));
  ClassicSoftBodyOptions o;
  o.kdp = 0.02;
  ClassicSoftBody sb(s, o);
  for (int k = 0; k < 240; ++k) ASSERT_TRUE(sb.step());
  double zmin = 1e9, zmax = -1e9;
  for (const Vec3& x : sb.positions()) {
    zmin = std::min(zmin, x.z());
    zmax = std::max(zmax, x.z());
  }
  std::cout << "[bullet-classic] patch on a plane after 1 s: node heights " << zmin << " .. " << zmax
            << " m (collision margin " << sb.plane_contact_offset() << " m)\n";
  for (const Vec3& x : sb.positions()) {
    EXPECT_GT(x.z(), -1e-3) << "fell through the plane";
    EXPECT_LT(x.z(), sb.plane_contact_offset() + 0.01) << "did not reach the plane";
  }
}

// Self-collision (off by default): clusters per triangle and the cluster collider run every step.
// A cloth laid over itself in two layers 2 cm apart and pushed together must not pass through.
TEST(BulletClassic, SelfCollisionOptionKeepsTwoLayersApart) {
  Scene s;
  s.dt = 1.0 / 240.0;
  // Two 3x3 patches (one Scene, one body), the upper one moving down onto the lower one.
  for (int layer = 0; layer < 2; ++layer) {
    ClothGridSpec c;
    c.rows = 3;
    c.cols = 3;
    c.spacing = 0.05;
    c.origin = Vec3(0, 0, 0.02 * layer);
    c.total_mass = 0.02;
    c.stiffness_b = 50.0;
    if (layer == 0) c.pins = {{0, 0}, {0, 2}, {2, 0}, {2, 2}};
    append_cloth(s, c);
  }
  for (int i = 9; i < 18; ++i) s.particles.v[i] = Vec3(0, 0, -0.5);
  ClassicSoftBodyOptions on;
  on.self_collision = true;
  ClassicSoftBodyOptions off;
  ClassicSoftBody with(s, on), without(s, off);
  bool mentions = false;
  for (const auto& n : with.not_modelled()) mentions = mentions || n.rfind("self-collision", 0) == 0;
  EXPECT_TRUE(mentions);
  for (int k = 0; k < 48; ++k) {
    ASSERT_TRUE(with.step());
    ASSERT_TRUE(without.step());
  }
  // Centre node of each layer: 4 (lower), 13 (upper).
  const double gap_with = with.positions()[13].z() - with.positions()[4].z();
  const double gap_without = without.positions()[13].z() - without.positions()[4].z();
  std::cout << "[bullet-classic] layer gap after 0.2 s: with self-collision " << gap_with << " m, without "
            << gap_without << " m\n";
  EXPECT_LT(gap_without, 0.0);  // without it the upper layer passes through
  EXPECT_GT(gap_with, 0.0);
}

// ---- the guarded fixed-time run on the tradeoff suite's curtain -------------------------------------

TEST(BulletClassicRun, IsBitForBitReproducibleAlsoOnConcurrentThreads) {
  const Scene s = testing::curtain(testing::kCurtainN);
  ClassicSoftBodyOptions cls;
  cls.klst = 0.05;
  cls.piterations = 4;
  cls.kdp = 0.0;
  const double h = testing::kCurtainH0, T = testing::kCurtainT;
  const GuardedRun c1 = run_classic_soft_body(s, h, T, cls), c2 = run_classic_soft_body(s, h, T, cls);
  ASSERT_TRUE(c1.x && c2.x);
  EXPECT_EQ(*c1.x, *c2.x);
  std::optional<std::vector<Vec3>> c3, c4;
  std::thread ta([&] { c3 = run_classic_soft_body(s, h, T, cls).x; });
  std::thread tb([&] { c4 = run_classic_soft_body(s, h, T, cls).x; });
  ta.join();
  tb.join();
  ASSERT_TRUE(c3 && c4);
  EXPECT_EQ(*c3, *c1.x);
  EXPECT_EQ(*c4, *c1.x);
}

TEST(BulletClassicRun, HugeStepReturnsABoundedClothOrAReason) {
  // The classic body keeps positions bounded by projection: at a huge step it either returns a
  // bounded (wrong) cloth or fails with a reason, but it returns after the fixed step count.
  const Scene s = testing::curtain(testing::kCurtainN);
  ClassicSoftBodyOptions o;
  o.klst = 1.0;
  o.kdp = 0.0;
  const GuardedRun c = run_classic_soft_body(s, 0.25, 10.0, o);
  if (c.x) {
    for (const Vec3& x : *c.x) EXPECT_TRUE(x.allFinite());
  } else {
    EXPECT_FALSE(c.reason.empty());
  }
}

}  // namespace
}  // namespace tecido::reference
