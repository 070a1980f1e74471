#pragma once
/// The `stability` suite's cases, indexed 0..case_count-1 in this order (the groups' order in
/// kCaseOrder: the longest groups first, so the threads finish together; Euler's horizon of 300
/// periods is the longest case of all, the groups of extremes come next):
///   horizon   grower x N periods: the growers' "largest stable step" over N periods;
///   extremes  one case per group of extremes (extreme_groups(): offset, mass ratio, near-zero
///             rest length, resting contact, tunnelling);
///   grid      bounded integrator x stiffness x mass: the largest stable step of one cell;
///   growth    grower x c x stiffness x mass: one run at h = c / omega.
/// Inside a group the last index varies fastest. Each case is a pure function of the settings and
/// its index; its result is JSON (the formats below).
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/stability/extremes.h"
#include "comparisons/suites/stability/oscillator.h"
#include "comparisons/suites/stability/settings.h"

#include <cstddef>
#include <vector>

namespace tecido::suites::stability {

enum class CaseGroup { Extremes, Grid, Horizon, Growth };
constexpr CaseGroup kCaseOrder[] = {CaseGroup::Horizon, CaseGroup::Extremes, CaseGroup::Grid, CaseGroup::Growth};

/// The number of cases of each group.
struct Layout {
  std::size_t extremes = 0, grid = 0, horizon = 0, growth = 0;
  std::size_t size(CaseGroup g) const;
};
/// From the settings and the number of groups of extremes.
Layout layout(const Settings& s, std::size_t extreme_groups);

/// A case: its group and its index inside the group.
struct CaseRef {
  CaseGroup group = CaseGroup::Extremes;
  std::size_t i = 0;
};
std::size_t case_count(const Layout& l);
/// The case at sweep index k (std::out_of_range past the end), and back.
CaseRef case_at(const Layout& l, std::size_t k);
std::size_t case_index(const Layout& l, CaseRef c);

/// Indices inside the grid group: settings.bounded[kind], stiffnesses[ks], masses[m].
struct GridCase {
  std::size_t kind = 0, ks = 0, m = 0;
};
GridCase grid_case(const Settings& s, std::size_t i);
std::size_t grid_index(const Settings& s, GridCase c);
/// Inside the horizon group: growers[grower], horizons[n].
struct HorizonCase {
  std::size_t grower = 0, n = 0;
};
HorizonCase horizon_case(const Settings& s, std::size_t i);
std::size_t horizon_index(const Settings& s, HorizonCase c);
/// Inside the growth group: growers[grower], growth_cs[c], stiffnesses[ks], masses[m].
struct GrowthCase {
  std::size_t grower = 0, c = 0, ks = 0, m = 0;
};
GrowthCase growth_case(const Settings& s, std::size_t i);
std::size_t growth_index(const Settings& s, GrowthCase c);

/// The groups of extremes, in case order.
std::vector<ExtremeGroup> extreme_groups();

/// Case results. Grid and horizon: a StableStep {"found","h","h_unstable","runs"}. Growth: a run
/// {"growth_per_step","finite","unstable_step"}. Extremes: result_json (extremes.h).
io::Json step_json(const StableStep& st);
StableStep step_from_json(const io::Json& j);
io::Json growth_json(const OscillatorRun& r);
OscillatorRun growth_from_json(const io::Json& j);

/// Runs case k.
io::Json run_case(const Settings& s, const std::vector<ExtremeGroup>& groups, const Layout& l, std::size_t k);

}  // namespace tecido::suites::stability
