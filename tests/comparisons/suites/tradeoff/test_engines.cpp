// The tradeoff suite's engines (comparisons/suites/tradeoff/engines.h) on its curtain: core's runs
// are reproducible, far beyond the stability limit a run fails with its reason instead of
// returning, RK4 converges, and every engine goes through the guarded runner. (The first test is a
// copy of the TradeoffEngines test of tests/comparisons/suites/test_stability_suite.cpp, whose old
// copy is to be deleted at integration.)
#include "comparisons/suites/tradeoff/engines.h"

#include "comparisons/suites/tradeoff/curtain.h"
#include "comparisons/suites/tradeoff/distances.h"
#include "comparisons/suites/tradeoff/theory.h"

#include <gtest/gtest.h>

namespace tecido::suites::tradeoff {
namespace {

TEST(TradeoffEngineSet, CoreIsReproducibleAndReportsInstability) {
  const Scene s = hanging_cloth(6);
  EXPECT_EQ(s.particles.size(), 36u);
  EXPECT_TRUE(s.particles.pinned[0] && s.particles.pinned[5]);
  const std::vector<TradeoffEngine> engines = tradeoff_engines();
  // Core's four come first; the reference build appends Bullet's (7 more).
  ASSERT_GE(engines.size(), 4u);
  EXPECT_EQ(engines[0].name, "core-euler");
  EXPECT_EQ(engines[3].name, "core-rk4");
  EXPECT_EQ(engines.size(), 11u);
  const double wb = omega_bound(s);
  const auto a = engines[1].run(s, 1.0 / wb, 0.25);
  const auto b = engines[1].run(s, 1.0 / wb, 0.25);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(max_abs_difference(*a, *b), 0.0);
  // Far beyond the stability limit the run is abandoned, not returned.
  EXPECT_FALSE(engines[1].run(s, 8.0 / wb, 4.0).has_value());
  // RK4 converges: halving the step changes the result by much less than the step before.
  const auto r1 = engines[3].run(s, 0.5 / wb, 0.25), r2 = engines[3].run(s, 0.25 / wb, 0.25),
             r3 = engines[3].run(s, 0.125 / wb, 0.25);
  ASSERT_TRUE(r1 && r2 && r3);
  EXPECT_LT(rms_distance(*r2, *r3), rms_distance(*r1, *r2) / 8.0);
}

TEST(TradeoffEngineSet, AFailedRunSaysWhereAndWhy) {
  const Scene s = hanging_cloth(6);
  const reference::GuardedRun r = core_tradeoff_engine(IntegratorKind::Euler).run_guarded(s, 8.0 / omega_bound(s), 4.0);
  EXPECT_FALSE(r.x.has_value());
  EXPECT_GT(r.failed_at_step, 0);
  EXPECT_FALSE(r.reason.empty());
}

TEST(TradeoffEngineSet, AnEngineThatCannotBeBuiltFailsItsRun) {
  TradeoffEngine e;
  e.name = "broken";
  e.make = [](const Scene&) -> std::unique_ptr<engines::DynamicsEngine> { throw std::runtime_error("planted"); };
  const reference::GuardedRun r = e.run_guarded(hanging_cloth(4), 0.01, 0.1);
  EXPECT_FALSE(r.x.has_value());
  EXPECT_EQ(r.reason, "not built: planted");
}

TEST(TradeoffEngineSet, RangesFromTheSettings) {
  Settings st;
  st.bullet.max_side_classic = 8;
  st.bullet.max_steps = 2;
  for (const TradeoffEngine& e : tradeoff_engines(st)) {
    if (e.name.rfind("core-", 0) == 0) {
      EXPECT_FALSE(skipped(e, 128, 10)) << e.name;
    } else if (e.name.rfind("bullet-classic", 0) == 0) {
      EXPECT_FALSE(skipped(e, 8, 1));
      EXPECT_TRUE(skipped(e, 9, 0));
      EXPECT_TRUE(skipped(e, 8, 2));
    }
  }
}

}  // namespace
}  // namespace tecido::suites::tradeoff
