// The one registry of dynamics engines (comparisons/engines/dynamics_engines.h): its order and
// names, the sources a suite asks for, what each entry claims, and that every entry builds an
// engine that steps a scene (core's and Bullet's) or reports a refusal (an outside engine's).
#include "comparisons/engines/dynamics_engines.h"

#include "comparisons/suites/tradeoff/curtain.h"
#include "tests/support/refusing_engine.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace tecido::engines {
namespace {

std::vector<std::string> names(const std::vector<DynamicsEntry>& entries) {
  std::vector<std::string> out;
  for (const DynamicsEntry& e : entries) out.push_back(e.name);
  return out;
}

DynamicsSources all_sources() {
  DynamicsSources s;
  s.core = s.bullet = s.outside = true;
  return s;
}

TEST(DynamicsRegistry, CoreThenBulletInOneOrder) {
  const std::vector<std::string> expected = {"euler",
                                             "symplectic",
                                             "midpoint",
                                             "rk4",
                                             "bullet-deformable",
                                             "bullet-deformable-implicit-it1",
                                             "bullet-deformable-implicit-it4",
                                             "bullet-deformable-implicit-it16",
                                             "bullet-classic-it1",
                                             "bullet-classic-it4",
                                             "bullet-classic-it16"};
  EXPECT_EQ(names(dynamics_engines(all_sources(), nullptr)), expected);
}

TEST(DynamicsRegistry, ASuiteGetsOnlyTheSourcesItAsksFor) {
  DynamicsSources core;
  core.core = true;
  const auto c = dynamics_engines(core, nullptr);
  ASSERT_EQ(c.size(), 4u);
  for (const DynamicsEntry& e : c) EXPECT_EQ(e.source, DynamicsSource::Core) << e.name;
  DynamicsSources bullet;
  bullet.bullet = true;
  const auto b = dynamics_engines(bullet, nullptr);
  ASSERT_EQ(b.size(), 7u);
  for (const DynamicsEntry& e : b) EXPECT_EQ(e.source, DynamicsSource::Bullet) << e.name;
  DynamicsSources outside_only;
  outside_only.outside = true;
  EXPECT_TRUE(dynamics_engines(outside_only, nullptr).empty());  // no engine loaded
}

TEST(DynamicsRegistry, CoreEntriesClaimTheirIntegratorsOrder) {
  const auto c = dynamics_engines(DynamicsSources{true, false, false}, nullptr);
  ASSERT_EQ(c.size(), 4u);
  const double orders[] = {1.0, 1.0, 2.0, 4.0};
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_EQ(c[i].integrator, core_integrators()[i]);
    EXPECT_EQ(c[i].claimed_order, orders[i]) << c[i].name;
    EXPECT_EQ(c[i].evaluations_per_step, evaluations_per_step(c[i].integrator)) << c[i].name;
    EXPECT_EQ(c[i].outside_engine, nullptr);
  }
}

TEST(DynamicsRegistry, CoreAndBulletEntriesBuildEnginesThatStep) {
  Scene scene = suites::tradeoff::hanging_cloth(4);
  scene.dt = 1e-3;
  for (const DynamicsEntry& e : dynamics_engines(DynamicsSources{true, true, false}, nullptr)) {
    if (e.name.rfind("bullet-classic", 0) == 0) continue;  // calibrates kLST first: the tradeoff tests run it
    std::unique_ptr<DynamicsEngine> engine = e.make(scene);
    ASSERT_NE(engine, nullptr) << e.name;
    EXPECT_TRUE(engine->advance(3)) << e.name;
    EXPECT_EQ(engine->steps_done(), 3) << e.name;
    EXPECT_EQ(engine->positions().size(), scene.particles.size()) << e.name;
  }
}

TEST(DynamicsRegistry, AnOutsideEntryKeepsItsEngineAndReportsARefusal) {
  const outside::OutsideEnginePtr refuser = std::make_shared<testing::RefusingEngine>();
  const DynamicsEntry e = outside_dynamics_entry(refuser);
  EXPECT_EQ(e.name, "refuser");
  EXPECT_EQ(e.source, DynamicsSource::Outside);
  EXPECT_EQ(e.outside_engine, refuser);
  EXPECT_EQ(e.claimed_order, 0.0);
  try {
    e.make(suites::tradeoff::hanging_cloth(4));
    FAIL() << "a refused scene must throw";
  } catch (const std::runtime_error& ex) {
    EXPECT_EQ(std::string(ex.what()), "not modelled by refuser: springs: not modelled");
  }
}

}  // namespace
}  // namespace tecido::engines
