// The stability suite's case index (comparisons/suites/stability/cases.*): every index maps to
// exactly one case and back, and the counts follow the settings, quick and full.
#include "comparisons/suites/stability/cases.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <tuple>

namespace tecido::suites::stability {
namespace {

TEST(StabilityCases, CountsFollowTheSettings) {
  // Quick: a 3 x 3 grid, 3 horizons; full: 7 x 7, 4 horizons; 2 bounded integrators, 2 growers,
  // 3 values of c and 5 groups of extremes in both.
  const Layout q = layout(settings(true), extreme_groups().size());
  EXPECT_EQ(q.extremes, 5u);
  EXPECT_EQ(q.grid, 2u * 9u);
  EXPECT_EQ(q.horizon, 2u * 3u);
  EXPECT_EQ(q.growth, 2u * 3u * 9u);
  EXPECT_EQ(case_count(q), 83u);
  const Layout f = layout(settings(false), extreme_groups().size());
  EXPECT_EQ(f.grid, 2u * 49u);
  EXPECT_EQ(f.horizon, 2u * 4u);
  EXPECT_EQ(f.growth, 2u * 3u * 49u);
  EXPECT_EQ(case_count(f), 5u + 98u + 8u + 294u);
}

TEST(StabilityCases, EveryIndexIsOneCaseAndBack) {
  for (bool quick : {true, false}) {
    const Settings s = settings(quick);
    const Layout l = layout(s, extreme_groups().size());
    std::set<std::pair<int, std::size_t>> seen;
    std::size_t per_group[4] = {0, 0, 0, 0};
    for (std::size_t k = 0; k < case_count(l); ++k) {
      const CaseRef c = case_at(l, k);
      ASSERT_LT(c.i, l.size(c.group)) << k;
      EXPECT_EQ(case_index(l, c), k);
      EXPECT_TRUE(seen.insert({static_cast<int>(c.group), c.i}).second) << k;
      ++per_group[static_cast<int>(c.group)];
    }
    EXPECT_EQ(per_group[static_cast<int>(CaseGroup::Extremes)], l.extremes);
    EXPECT_EQ(per_group[static_cast<int>(CaseGroup::Grid)], l.grid);
    EXPECT_EQ(per_group[static_cast<int>(CaseGroup::Horizon)], l.horizon);
    EXPECT_EQ(per_group[static_cast<int>(CaseGroup::Growth)], l.growth);
    EXPECT_THROW(case_at(l, case_count(l)), std::out_of_range);
    EXPECT_THROW(case_index(l, {CaseGroup::Grid, l.grid}), std::out_of_range);
  }
}

TEST(StabilityCases, TheLongestGroupsComeFirst) {
  // Quick: 6 horizons, then 5 groups of extremes, then the grid.
  const Layout l = layout(settings(true), 5);
  for (std::size_t k = 0; k < 6; ++k) EXPECT_EQ(case_at(l, k).group, CaseGroup::Horizon) << k;
  for (std::size_t k = 6; k < 11; ++k) EXPECT_EQ(case_at(l, k).group, CaseGroup::Extremes) << k;
  EXPECT_EQ(case_at(l, 11).group, CaseGroup::Grid);
  EXPECT_EQ(case_index(l, {CaseGroup::Growth, 0}), 6u + 5u + 18u);
}

TEST(StabilityCases, InnerIndicesCoverEveryCombinationOnce) {
  const Settings s = settings(true);
  const Layout l = layout(s, 5);
  std::set<std::tuple<std::size_t, std::size_t, std::size_t>> grid;
  for (std::size_t i = 0; i < l.grid; ++i) {
    const GridCase c = grid_case(s, i);
    ASSERT_LT(c.kind, s.bounded.size());
    ASSERT_LT(c.ks, s.stiffnesses.size());
    ASSERT_LT(c.m, s.masses.size());
    EXPECT_EQ(grid_index(s, c), i);
    grid.insert({c.kind, c.ks, c.m});
  }
  EXPECT_EQ(grid.size(), l.grid);
  // The mass varies fastest: case 1 is the first cell's next mass.
  EXPECT_EQ(grid_case(s, 1).m, 1u);
  EXPECT_EQ(grid_case(s, 1).ks, 0u);
  std::set<std::pair<std::size_t, std::size_t>> horizon;
  for (std::size_t i = 0; i < l.horizon; ++i) {
    const HorizonCase c = horizon_case(s, i);
    EXPECT_EQ(horizon_index(s, c), i);
    horizon.insert({c.grower, c.n});
  }
  EXPECT_EQ(horizon.size(), l.horizon);
  std::set<std::tuple<std::size_t, std::size_t, std::size_t, std::size_t>> growth;
  for (std::size_t i = 0; i < l.growth; ++i) {
    const GrowthCase c = growth_case(s, i);
    ASSERT_LT(c.grower, s.growers.size());
    ASSERT_LT(c.c, s.growth_cs.size());
    EXPECT_EQ(growth_index(s, c), i);
    growth.insert({c.grower, c.c, c.ks, c.m});
  }
  EXPECT_EQ(growth.size(), l.growth);
}

TEST(StabilityCases, ResultsRoundTripThroughJson) {
  const StableStep st{true, 0.1 + 0.2, INFINITY, 17};
  const StableStep back = step_from_json(io::Json::parse(step_json(st).dump()));
  EXPECT_EQ(back.found, st.found);
  EXPECT_EQ(back.h, st.h);
  EXPECT_EQ(back.h_unstable, st.h_unstable);
  EXPECT_EQ(back.runs, st.runs);
  OscillatorRun r;
  r.finite = false;
  r.unstable_step = 12;
  r.growth_per_step = INFINITY;
  const OscillatorRun g = growth_from_json(io::Json::parse(growth_json(r).dump()));
  EXPECT_FALSE(g.finite);
  EXPECT_EQ(g.unstable_step, 12);
  EXPECT_EQ(g.growth_per_step, INFINITY);
}

}  // namespace
}  // namespace tecido::suites::stability
