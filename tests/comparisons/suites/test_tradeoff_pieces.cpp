// Pieces of the `tradeoff` suite on tiny inputs with known answers: the Pareto front, distances,
// and the engines it runs.
#include "comparisons/suites/tradeoff_suite.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

namespace tecido::suites {
namespace {

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

}  // namespace
}  // namespace tecido::suites
