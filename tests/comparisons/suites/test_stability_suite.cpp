// Statistics of the `stability` and `tradeoff` suites on tiny inputs with known answers.
#include "tests/support/cli_runner.h"
#include "comparisons/suites/stability_suite.h"
#include "comparisons/suites/tradeoff_suite.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

namespace tecido::suites {
namespace {

TEST(FindMaxStableStep, BracketsAndBisectsAPlantedThreshold) {
  // Stable exactly for h <= 0.7: from 0.1 it doubles to 0.2, 0.4, 0.8 (unstable), then bisects.
  int calls = 0;
  const StableStep up = find_max_stable_step([&](double h) { return ++calls, h <= 0.7; }, 0.1, 1e-9);
  ASSERT_TRUE(up.found);
  EXPECT_LE(up.h, 0.7);
  EXPECT_GT(up.h_unstable, 0.7);
  EXPECT_LE(up.h_unstable - up.h, 1e-9 * up.h);
  EXPECT_EQ(up.runs, calls);
  // From above: halves 3.0 -> 1.5 -> 0.75 (unstable) -> 0.375 (stable).
  const StableStep down = find_max_stable_step([](double h) { return h <= 0.7; }, 3.0, 1e-9);
  ASSERT_TRUE(down.found);
  EXPECT_NEAR(down.h, 0.7, 1e-9);
  // Same predicate, same start: the same sequence of calls and the same answer, bit for bit.
  const StableStep again = find_max_stable_step([](double h) { return h <= 0.7; }, 3.0, 1e-9);
  EXPECT_EQ(again.h, down.h);
  EXPECT_EQ(again.runs, down.runs);
}

TEST(FindMaxStableStep, ReportsWhenNothingIsStable) {
  const StableStep r = find_max_stable_step([](double) { return false; }, 1.0, 1e-6, 10, 10);
  EXPECT_FALSE(r.found);
  EXPECT_EQ(r.runs, 11);
  EXPECT_DOUBLE_EQ(r.h_unstable, 1.0 / 1024.0);
}

TEST(Amplification, MatchesTheLinearTheory) {
  EXPECT_DOUBLE_EQ(amplification(IntegratorKind::Symplectic, 1.999), 1.0);
  EXPECT_GT(amplification(IntegratorKind::Symplectic, 2.001), 1.0);
  EXPECT_NEAR(amplification(IntegratorKind::RK4, 2.0 * std::sqrt(2.0)), 1.0, 1e-12);
  EXPECT_LT(amplification(IntegratorKind::RK4, 2.8), 1.0);
  EXPECT_GT(amplification(IntegratorKind::RK4, 2.85), 1.0);
  for (double c : {1e-3, 0.1, 1.0}) {
    EXPECT_GT(amplification(IntegratorKind::Euler, c), 1.0);
    EXPECT_GT(amplification(IntegratorKind::Midpoint, c), 1.0);
  }
}

TEST(Oscillator, SymplecticLimitIsTwoOverOmega) {
  // ks = 4 N/m, m = 1 kg: omega = 2 1/s, so h_max = 1 s; to 3 digits of h omega = 2.
  const StableStep s = oscillator_max_step(IntegratorKind::Symplectic, 4.0, 1.0, 200.0, 1000.0, 1e-6);
  ASSERT_TRUE(s.found);
  EXPECT_NEAR(s.h * 2.0, 2.0, 1e-3);
  EXPECT_LE(s.h * 2.0, 2.0);  // stable below the limit only
}

TEST(Oscillator, RK4LimitIsTwoRootTwoOverOmega) {
  const StableStep s = oscillator_max_step(IntegratorKind::RK4, 1e4, 1e-2, 200.0, 1000.0, 1e-6);  // omega = 1000
  ASSERT_TRUE(s.found);
  EXPECT_NEAR(s.h * 1000.0, 2.0 * std::sqrt(2.0), 1e-2);
}

TEST(Oscillator, EulerGrowthPerStepIsItsAmplification) {
  // Euler's update is a scaled rotation of (x, v/omega): the norm grows by sqrt(1 + c^2) per step.
  const double c = 0.1;
  const OscillatorRun r = run_oscillator(IntegratorKind::Euler, 9.0, 1.0, c / 3.0, 5.0, 1e3);
  ASSERT_TRUE(r.finite);
  EXPECT_TRUE(r.bounded);
  EXPECT_NEAR(r.growth_per_step, std::sqrt(1.0 + c * c), 1e-13);
  const OscillatorRun m = run_oscillator(IntegratorKind::Midpoint, 9.0, 1.0, c / 3.0, 5.0, 1e3);
  EXPECT_NEAR(m.growth_per_step, std::sqrt(1.0 + c * c * c * c / 4.0), 1e-13);
}

TEST(ParetoFront, PlantedSet) {
  const double nan = std::nan("");
  const std::vector<CostError> pts = {
      {1.0, 10.0},  // 0 front (cheapest finite... but see 6)
      {2.0, 5.0},   // 1 front
      {3.0, 5.0},   // 2 dominated by 1 (same error, dearer)
      {2.0, 6.0},   // 3 dominated by 1 (same cost, worse)
      {4.0, 1.0},   // 4 front
      {5.0, 1.0},   // 5 dominated by 4
      {0.5, 20.0},  // 6 front: cheapest
      {nan, 0.1},   // 7 ignored
      {4.0, 1.0},   // 8 equal to 4: both kept
      {6.0, 0.5},   // 9 front: most accurate
      {7.0, 0.5},   // 10 dominated by 9
  };
  const std::vector<int> want = {6, 0, 1, 4, 8, 9};
  EXPECT_EQ(pareto_front(pts), want);
  EXPECT_TRUE(pareto_front({}).empty());
  EXPECT_EQ(pareto_front({{1.0, 1.0}}), std::vector<int>{0});
}

TEST(Distances, RmsAndMaxAbs) {
  const std::vector<Vec3> a = {Vec3(0, 0, 0), Vec3(1, 1, 1)};
  const std::vector<Vec3> b = {Vec3(3, 4, 0), Vec3(1, 1, 1)};
  EXPECT_DOUBLE_EQ(rms_distance(a, b), std::sqrt(25.0 / 2.0));
  EXPECT_DOUBLE_EQ(max_abs_difference(a, b), 4.0);
  EXPECT_EQ(max_abs_difference(a, a), 0.0);
  std::vector<Vec3> c = a;
  c[1].x() = std::nan("");
  EXPECT_EQ(max_abs_difference(a, c), std::numeric_limits<double>::infinity());
}

TEST(TradeoffEngines, CoreIsReproducibleAndReportsInstability) {
  const Scene s = hanging_cloth(6);
  EXPECT_EQ(s.particles.size(), 36u);
  EXPECT_TRUE(s.particles.pinned[0] && s.particles.pinned[5]);
  const std::vector<TradeoffEngine> engines = tradeoff_engines();
  // Core's four come first; the reference build appends Bullet's (7 more).
  ASSERT_GE(engines.size(), 4u);
  EXPECT_EQ(engines[0].name, "core-euler");
  EXPECT_EQ(engines[3].name, "core-rk4");
#ifdef TECIDO_HAVE_REFERENCE
  EXPECT_EQ(engines.size(), 11u);
#else
  EXPECT_EQ(engines.size(), 4u);
#endif
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

TEST(SuiteCli, StabilityQuickPasses) {
  const auto dir = testing::temp_dir("suite-stability");
  const auto r = testing::run_cli("suite stability --quick --out '" + dir.string() + "'");
  EXPECT_EQ(r.code, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(testing::slurp(dir / "report.json"));
  ASSERT_EQ(j["suites"].size(), 1u);
  EXPECT_GE(j["suites"][0]["checks"].size(), 10u);
  for (const auto& c : j["suites"][0]["checks"]) EXPECT_TRUE(c["pass"].get<bool>()) << c.dump();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tecido::suites
