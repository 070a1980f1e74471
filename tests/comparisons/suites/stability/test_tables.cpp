// The stability suite's tables (comparisons/suites/stability/tables.*) from synthetic case results
// whose ratios are worked by hand; no simulation runs.
#include "comparisons/suites/stability/tables.h"
#include "comparisons/suites/stability/theory.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::stability {
namespace {

/// One bounded integrator (symplectic) and one grower (euler) on a 1 x 2 grid: ks = 4 N/m, m = 1 and
/// 4 kg, so omega = 2 and 1; one c, one horizon; no groups of extremes.
Settings tiny() {
  Settings s = settings(true);
  s.stiffnesses = {4.0};
  s.masses = {1.0, 4.0};
  s.bounded = {IntegratorKind::Symplectic};
  s.growers = {IntegratorKind::Euler};
  s.growth_cs = {1.0};
  s.horizons = {10.0};
  return s;
}

/// Grid h = 0.99 s (omega 2: h omega 1.98) and 1.96 s (omega 1: 1.96); growth per step sqrt 2 on both
/// cells (Euler's exact amplification at c = 1); horizon 1.01 x the prediction.
std::vector<io::Json> results(const Settings& s, const Layout& l) {
  std::vector<io::Json> r(case_count(l));
  r[case_index(l, {CaseGroup::Grid, 0})] = step_json({true, 0.99, 0.99 * (1 + 1e-6), 20});
  r[case_index(l, {CaseGroup::Grid, 1})] = step_json({true, 1.96, 1.96 * (1 + 1e-6), 22});
  for (std::size_t i = 0; i < 2; ++i) {
    OscillatorRun run;
    run.growth_per_step = std::sqrt(2.0);
    r[case_index(l, {CaseGroup::Growth, i})] = growth_json(run);
  }
  const double pred = horizon_prediction(IntegratorKind::Euler, 10.0, s.amplitude_bound);
  r[case_index(l, {CaseGroup::Horizon, 0})] = step_json({true, 1.01 * pred, 1.02 * pred, 15});
  return r;
}

TEST(StabilityTables, GridRatiosAndSpreadByHand) {
  const Settings s = tiny();
  const Layout l = layout(s, 0);
  const GridTable t = grid_table(s, l, 0, results(s, l));
  ASSERT_EQ(t.cells.size(), 2u);
  EXPECT_DOUBLE_EQ(t.cells[0].h_omega, 1.98);
  EXPECT_DOUBLE_EQ(t.cells[1].h_omega, 1.96);
  EXPECT_DOUBLE_EQ(t.ratio.lo(), 0.98);
  EXPECT_DOUBLE_EQ(t.ratio.hi(), 0.99);
  EXPECT_DOUBLE_EQ(t.h_omega.spread(), 1.98 / 1.96 - 1.0);
  EXPECT_EQ(t.runs, 42);
}

TEST(StabilityTables, GrowthOfEulerAtItsExactAmplificationHasNoError) {
  const Settings s = tiny();
  const Layout l = layout(s, 0);
  const GrowthTable t = growth_table(s, l, 0, results(s, l));
  ASSERT_EQ(t.rows.size(), 1u);
  // sqrt(2)^(2 pi) = 2^pi per period, theory and measurement alike.
  EXPECT_NEAR(t.rows[0].theory, std::pow(2.0, kPi), 1e-12);
  EXPECT_NEAR(t.rows[0].growth.lo(), std::pow(2.0, kPi), 1e-12);
  EXPECT_LT(t.worst.hi(), 1e-14);
  // A growth per step of sqrt(2)(1 + e) is off by 2 ln(1 + e) / ln 2 in log growth.
  std::vector<io::Json> r = results(s, l);
  OscillatorRun off;
  off.growth_per_step = std::sqrt(2.0) * (1.0 + 1e-3);
  r[case_index(l, {CaseGroup::Growth, 1})] = growth_json(off);
  EXPECT_NEAR(growth_table(s, l, 0, r).worst.hi(), 2.0 * std::log1p(1e-3) / std::log(2.0), 1e-12);
}

TEST(StabilityTables, HorizonRatio) {
  const Settings s = tiny();
  const Layout l = layout(s, 0);
  const HorizonTable t = horizon_table(s, l, 0, results(s, l));
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_DOUBLE_EQ(t.rows[0].ratio, 1.01);
  EXPECT_DOUBLE_EQ(t.ratio.lo(), 1.01);
}

TEST(StabilityTables, MissingValuesNameTheirCell) {
  const Settings s = tiny();
  const Layout l = layout(s, 0);
  std::vector<io::Json> r = results(s, l);
  r[case_index(l, {CaseGroup::Grid, 1})] = io::Json{{"error", "case 1 threw: boom"}};
  r[case_index(l, {CaseGroup::Horizon, 0})] = step_json({false, 0.0, 0.001, 13});
  OscillatorRun nan_run;
  nan_run.growth_per_step = std::nan("");
  r[case_index(l, {CaseGroup::Growth, 0})] = growth_json(nan_run);
  const GridTable g = grid_table(s, l, 0, r);
  EXPECT_EQ(g.ratio.reason(), "ks = 4 N/m, m = 4 kg: case 1 threw: boom");
  EXPECT_TRUE(std::isnan(g.ratio.lo()));
  EXPECT_EQ(g.cells[1].missing, g.ratio.reason());
  EXPECT_EQ(horizon_table(s, l, 0, r).ratio.reason(), "no stable step over 10 periods (unstable down to h omega = 0.001)");
  EXPECT_EQ(growth_table(s, l, 0, r).worst.reason(), "NaN at c = 1, ks = 4 N/m, m = 1 kg");
}

}  // namespace
}  // namespace tecido::suites::stability
