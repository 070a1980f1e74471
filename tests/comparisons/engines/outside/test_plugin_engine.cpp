// The example plug-in through PluginEngine: its MT test on hand-worked pairs (the seed's AND rule
// misses a stab, a coplanar overlap and a touch), its explicit Euler against one step worked by hand
// and against the closed form of free fall, and its refusal of features it does not model.
#include "comparisons/engines/outside/plugin_engine.h"
#include "comparisons/engines/outside/plugin_library.h"
#include "tests/support/outside_fixtures.h"

#include <gtest/gtest.h>

namespace tecido::outside {
namespace {

OutsideEnginePtr engine(const std::string& name) {
  for (auto& e : plugin_engines(PluginLibrary::load(testing::kExamplePlugin)))
    if (e->name() == name) return e;
  return nullptr;
}

TEST(PluginEngine, Capabilities) {
  const auto mt = engine("mt-plugin"), euler = engine("euler-plugin");
  ASSERT_TRUE(mt && euler);
  EXPECT_TRUE(mt->capabilities().tri_tri);
  EXPECT_FALSE(mt->capabilities().dynamics);
  EXPECT_FALSE(mt->claimed_order().has_value());
  EXPECT_TRUE(euler->capabilities().dynamics);
  EXPECT_FALSE(euler->capabilities().tri_tri);
  EXPECT_EQ(euler->claimed_order(), 1.0);
  EXPECT_FALSE(euler->is_process());
}

TEST(PluginEngine, MollerTrumboreOnHandWorkedPairs) {
  const auto mt = engine("mt-plugin");
  std::vector<TriTriQuery> qs;
  for (const auto& p : testing::hand_pairs()) qs.push_back({p.a, p.b});
  const auto answers = mt->tri_tri(qs);
  ASSERT_EQ(answers.size(), qs.size());
  for (std::size_t k = 0; k < qs.size(); ++k) {
    ASSERT_TRUE(answers[k].has_value());
    EXPECT_EQ(*answers[k], testing::hand_pairs()[k].mt) << testing::hand_pairs()[k].id;
  }
}

/// Two particles on a spring (k = 2, l = 1, masses 1 and 2) stretched to 1.5, gravity -1 in z, drag 0.5.
Scene spring_scene() {
  Scene s;
  s.dt = 0.1;
  s.particles.add(Vec3(0, 0, 0), Vec3(1, 0, 0), 1.0, 1.0, false);
  s.particles.add(Vec3(1.5, 0, 0), Vec3(0, 0, 2), 2.0, 1.0, false);
  s.forces.springs.push_back(Spring{0, 1, 2.0, 1.0, 0.0});
  s.forces.gravity = Vec3(0, 0, -1);
  s.forces.air_drag = 0.5;
  return s;
}

TEST(PluginEngine, EulerOneStepByHand) {
  Creation c = engine("euler-plugin")->create(spring_scene());
  ASSERT_TRUE(c.simulation) << c.refusal;
  ASSERT_TRUE(c.simulation->step());
  // Spring force on 0: 2 (1.5 - 1) = 1 N along +x; on 1: -1 N. Drag -0.5 v.
  // a0 = (1 - 0.5, 0, -1) / 1 = (0.5, 0, -1); a1 = (-1/2, 0, -1 - 0.5*2/2) = (-0.5, 0, -1.5).
  const auto x = c.simulation->positions(), v = c.simulation->velocities();
  EXPECT_DOUBLE_EQ(x[0].x(), 0.1);  // x += h v(t)
  EXPECT_DOUBLE_EQ(x[1].z(), 0.2);
  EXPECT_DOUBLE_EQ(v[0].x(), 1.05);  // v += h a(t)
  EXPECT_DOUBLE_EQ(v[0].z(), -0.1);
  EXPECT_DOUBLE_EQ(v[1].x(), -0.05);
  EXPECT_DOUBLE_EQ(v[1].z(), 1.85);
  EXPECT_EQ(c.simulation->steps_done(), 1);
  EXPECT_DOUBLE_EQ(c.simulation->time(), 0.1);
}

TEST(PluginEngine, AdvanceIsStepsInOneCall) {
  Creation a = engine("euler-plugin")->create(spring_scene());
  Creation b = engine("euler-plugin")->create(spring_scene());
  ASSERT_TRUE(a.simulation && b.simulation);
  for (int i = 0; i < 7; ++i) ASSERT_TRUE(a.simulation->step());
  ASSERT_TRUE(b.simulation->advance(7));
  EXPECT_EQ(a.simulation->positions(), b.simulation->positions());  // bit for bit
  EXPECT_EQ(b.simulation->steps_done(), 7);
}

TEST(PluginEngine, FreeFallAgainstClosedForm) {
  // Explicit Euler on x'' = g from rest: x_n = g h^2 n (n - 1) / 2, v_n = g h n.
  Scene s;
  s.dt = 0.25;
  s.particles.add(Vec3::Zero(), Vec3::Zero(), 1.0, 1.0, false);
  s.forces.gravity = Vec3(0, 0, -8);
  Creation c = engine("euler-plugin")->create(s);
  ASSERT_TRUE(c.simulation->advance(4));
  EXPECT_DOUBLE_EQ(c.simulation->positions()[0].z(), -8 * 0.0625 * 4 * 3 / 2);
  EXPECT_DOUBLE_EQ(c.simulation->velocities()[0].z(), -8 * 0.25 * 4);
}

TEST(PluginEngine, PinnedParticleNeverMoves) {
  Scene s = spring_scene();
  s.particles = Particles{};
  s.particles.add(Vec3(0, 0, 0), Vec3::Zero(), 0.0, 1.0, true);
  s.particles.add(Vec3(1.5, 0, 0), Vec3::Zero(), 1.0, 1.0, false);
  Creation c = engine("euler-plugin")->create(s);
  ASSERT_TRUE(c.simulation->advance(10));
  EXPECT_EQ(c.simulation->positions()[0], Vec3::Zero());
}

TEST(PluginEngine, RefusesFeaturesItDoesNotModel) {
  Scene s = spring_scene();
  s.forces.wind = Wind{};
  Creation c = engine("euler-plugin")->create(s);
  EXPECT_FALSE(c.simulation);
  EXPECT_NE(c.refusal.find("feature bits 0x1"), std::string::npos) << c.refusal;  // TECIDO_FEATURE_WIND
}

TEST(PluginEngine, NonFiniteStateEndsTheRun) {
  Scene s;
  s.dt = 1.0;
  s.particles.add(Vec3::Zero(), Vec3(1e308, 0, 0), 1.0, 1.0, false);
  s.forces.air_drag = 1e10;  // v += h (-c v): overflows to -inf at once
  Creation c = engine("euler-plugin")->create(s);
  EXPECT_FALSE(c.simulation->advance(3));
  EXPECT_FALSE(c.simulation->step());  // stays failed
}

}  // namespace
}  // namespace tecido::outside
