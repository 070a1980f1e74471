// Outside engines in the drift suite (comparisons/suites/drift/outside_drift.h): the example
// plug-in's explicit Euler and the Python example's midpoint on the two-body scene give the
// figures core's integrator of the same method gives (the same arithmetic up to the order of
// operations, over a short run); momentum is conserved through both doors; a refused scene throws
// "not modelled by NAME"; planted results set or fail the momentum check with their reason.
#include "comparisons/engines/outside/plugin_engine.h"
#include "comparisons/engines/outside/plugin_library.h"
#include "comparisons/engines/outside/process_engine.h"
#include "comparisons/suites/drift/outside_drift.h"
#include "tests/support/outside_fixtures.h"
#include "tests/support/refusing_engine.h"

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>

namespace tecido::suites::drift {
namespace {

using namespace std::chrono_literals;

outside::OutsideEnginePtr euler_plugin() {
  for (auto& e : outside::plugin_engines(outside::PluginLibrary::load(testing::kExamplePlugin)))
    if (e->name() == "euler-plugin") return e;
  return nullptr;
}

Settings short_run() {
  Settings s;
  s.steps = 4000;
  return s;
}

/// The outside run against core's run of the same method: every figure to 1e-6 relative (the
/// midpoint's energy error is about 1e-8 of the energy, so round-off in E(t) - E0 shows at 1e-8 of it).
void expect_as_core(const InvariantRun& o, const InvariantRun& c) {
  EXPECT_EQ(o.unstable_at_step, 0);
  EXPECT_NEAR(o.max_rel_energy, c.max_rel_energy, 1e-6 * c.max_rel_energy);
  EXPECT_NEAR(o.final_rel_energy, c.final_rel_energy, 1e-6 * c.final_rel_energy);
  EXPECT_NEAR(o.growth_rate, c.growth_rate, 1e-6 * std::abs(c.growth_rate));
  EXPECT_NEAR(o.angular_momentum_error, c.angular_momentum_error, 1e-6 * c.angular_momentum_error);
  EXPECT_LT(o.momentum_error, 1e-13);
  ASSERT_EQ(o.energy_curve.size(), c.energy_curve.size());
}

TEST(OutsideDrift, EulerPluginDriftsAsCoresEuler) {
  const Scene two_body = conservative_scenes(1).at(0).scene;
  const auto e = euler_plugin();
  ASSERT_TRUE(e);
  const InvariantRun o = run_outside_invariants(*e, two_body, short_run());
  const InvariantRun c = run_invariants(two_body, IntegratorKind::Euler, short_run());
  expect_as_core(o, c);
  EXPECT_GT(o.last_over_first_half, 1.0);  // explicit Euler's energy grows
  EXPECT_GT(o.max_rel_energy, 1e-6);
}

TEST(OutsideDrift, PythonMidpointDriftsAsCoresMidpoint) {
  const Scene two_body = conservative_scenes(1).at(0).scene;
  const auto e = outside::ProcessEngine::start("py", testing::kPythonEngine, 30s);
  const InvariantRun o = run_outside_invariants(*e, two_body, short_run());
  const InvariantRun c = run_invariants(two_body, IntegratorKind::Midpoint, short_run());
  expect_as_core(o, c);
  const InvariantRun euler = run_invariants(two_body, IntegratorKind::Euler, short_run());
  EXPECT_LT(o.max_rel_energy, 1e-2 * euler.max_rel_energy);  // order 2: far below Euler's drift
  EXPECT_EQ(e->round_trips(), 1 + 1 + short_run().steps / short_run().sample_every);  // hello, create, one per sample
}

TEST(OutsideDrift, RefusalThrowsNotModelled) {
  testing::RefusingEngine r;
  try {
    run_outside_invariants(r, conservative_scenes(1).at(0).scene, short_run());
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "not modelled by refuser: springs: not modelled");
  }
}

TEST(OutsideDrift, PlantedResultsSetOrFailTheMomentumCheck) {
  const std::vector<Conservative> scenes = conservative_scenes(1);
  const std::vector<outside::OutsideEnginePtr> engines = {std::make_shared<testing::RefusingEngine>()};
  const Tolerances tol(io::Json::parse(R"({"drift":{"momentum_rel":1e-12}})"), "planted");
  CheckList checks;
  declare_outside_drift(checks, scenes, engines, tol);
  ASSERT_EQ(scenes.size(), 2u);
  InvariantRun ok;
  ok.steps = 10;
  ok.momentum_error = 3e-13;
  const std::vector<io::Json> results = {invariant_json(ok),
                                         io::Json{{"error", "case 9 threw: not modelled by refuser: springs"}}};
  io::Json data;
  const std::string md = outside_drift_markdown(scenes, engines, results, checks, data);
  const auto done = checks.finish();
  ASSERT_EQ(done.size(), 2u);
  EXPECT_EQ(done[0].name, "drift/" + scenes[0].name + "/refuser/momentum");
  EXPECT_TRUE(done[0].pass);
  EXPECT_EQ(done[0].value, 3e-13);
  EXPECT_FALSE(done[1].pass);
  EXPECT_NE(done[1].reason.find("not modelled by refuser"), std::string::npos) << done[1].reason;
  EXPECT_NE(md.find("- refuser: test"), std::string::npos) << md;  // the engine with its door
  EXPECT_NE(md.find("not modelled by refuser"), std::string::npos) << md;
  EXPECT_TRUE(data[scenes[0].name].contains("refuser"));
}

}  // namespace
}  // namespace tecido::suites::drift
