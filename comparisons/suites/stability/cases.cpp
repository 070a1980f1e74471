#include "comparisons/suites/stability/cases.h"

#include "comparisons/suites/stability/mass_ratio.h"
#include "comparisons/suites/stability/near_zero.h"
#include "comparisons/suites/stability/offset.h"
#include "comparisons/suites/stability/resting.h"
#include "comparisons/suites/stability/tunnelling.h"
#include "comparisons/suites/sweep.h"

#include <cmath>
#include <stdexcept>

namespace tecido::suites::stability {

std::size_t Layout::size(CaseGroup g) const {
  switch (g) {
    case CaseGroup::Extremes: return extremes;
    case CaseGroup::Grid: return grid;
    case CaseGroup::Horizon: return horizon;
    case CaseGroup::Growth: return growth;
  }
  return 0;
}

Layout layout(const Settings& s, std::size_t extreme_groups) {
  const std::size_t cells = s.stiffnesses.size() * s.masses.size();
  return {extreme_groups, s.bounded.size() * cells, s.growers.size() * s.horizons.size(),
          s.growers.size() * s.growth_cs.size() * cells};
}

std::size_t case_count(const Layout& l) { return l.extremes + l.grid + l.horizon + l.growth; }

CaseRef case_at(const Layout& l, std::size_t k) {
  for (CaseGroup g : kCaseOrder) {
    if (k < l.size(g)) return {g, k};
    k -= l.size(g);
  }
  throw std::out_of_range("stability: case index past the last case");
}

std::size_t case_index(const Layout& l, CaseRef c) {
  if (c.i >= l.size(c.group)) throw std::out_of_range("stability: case outside its group");
  std::size_t k = 0;
  for (CaseGroup g : kCaseOrder) {
    if (g == c.group) break;
    k += l.size(g);
  }
  return k + c.i;
}

GridCase grid_case(const Settings& s, std::size_t i) {
  const std::size_t nm = s.masses.size(), cells = s.stiffnesses.size() * nm;
  return {i / cells, (i % cells) / nm, i % nm};
}

std::size_t grid_index(const Settings& s, GridCase c) {
  return (c.kind * s.stiffnesses.size() + c.ks) * s.masses.size() + c.m;
}

HorizonCase horizon_case(const Settings& s, std::size_t i) { return {i / s.horizons.size(), i % s.horizons.size()}; }

std::size_t horizon_index(const Settings& s, HorizonCase c) { return c.grower * s.horizons.size() + c.n; }

GrowthCase growth_case(const Settings& s, std::size_t i) {
  const std::size_t nm = s.masses.size(), cells = s.stiffnesses.size() * nm, per_grower = s.growth_cs.size() * cells;
  return {i / per_grower, (i % per_grower) / cells, (i % cells) / nm, i % nm};
}

std::size_t growth_index(const Settings& s, GrowthCase c) {
  return ((c.grower * s.growth_cs.size() + c.c) * s.stiffnesses.size() + c.ks) * s.masses.size() + c.m;
}

std::vector<ExtremeGroup> extreme_groups() {
  return {{"offset", &offset_checks, &run_offset},
          {"mass ratio", &mass_ratio_checks, &run_mass_ratio},
          {"near-zero rest length", &near_zero_checks, &run_near_zero},
          {"resting contact", &resting_checks, &run_resting},
          {"tunnelling", &tunnelling_checks, &run_tunnelling}};
}

io::Json step_json(const StableStep& st) {
  return {{"found", st.found}, {"h", num(st.h)}, {"h_unstable", num(st.h_unstable)}, {"runs", st.runs}};
}

StableStep step_from_json(const io::Json& j) {
  StableStep st;
  st.found = j.at("found").get<bool>();
  st.h = get_num(j.at("h"));
  st.h_unstable = get_num(j.at("h_unstable"));
  st.runs = j.at("runs").get<int>();
  return st;
}

io::Json growth_json(const OscillatorRun& r) {
  return {{"growth_per_step", num(r.growth_per_step)}, {"finite", r.finite}, {"unstable_step", r.unstable_step}};
}

OscillatorRun growth_from_json(const io::Json& j) {
  OscillatorRun r;
  r.growth_per_step = get_num(j.at("growth_per_step"));
  r.finite = j.at("finite").get<bool>();
  r.unstable_step = j.at("unstable_step").get<long long>();
  return r;
}

namespace {

io::Json run_grid(const Settings& s, std::size_t i) {
  const GridCase c = grid_case(s, i);
  return step_json(oscillator_max_step(s.bounded[c.kind], s.stiffnesses[c.ks], s.masses[c.m], s.periods,
                                       s.amplitude_bound, s.rel_tol, s.max_doublings, s.max_halvings));
}

/// ks = 1 N/m, m = 1 kg (omega = 1), over N periods.
io::Json run_horizon(const Settings& s, std::size_t i) {
  const HorizonCase c = horizon_case(s, i);
  return step_json(oscillator_max_step(s.growers[c.grower], 1.0, 1.0, s.horizons[c.n], s.amplitude_bound,
                                       s.horizon_rel_tol, s.max_doublings, s.max_halvings));
}

io::Json run_growth(const Settings& s, std::size_t i) {
  const GrowthCase c = growth_case(s, i);
  const double ks = s.stiffnesses[c.ks], m = s.masses[c.m], omega = std::sqrt(ks / m);
  return growth_json(
      run_oscillator(s.growers[c.grower], ks, m, s.growth_cs[c.c] / omega, s.growth_periods, s.amplitude_bound));
}

}  // namespace

io::Json run_case(const Settings& s, const std::vector<ExtremeGroup>& groups, const Layout& l, std::size_t k) {
  const CaseRef c = case_at(l, k);
  switch (c.group) {
    case CaseGroup::Extremes: return result_json(groups.at(c.i).run(s));
    case CaseGroup::Grid: return run_grid(s, c.i);
    case CaseGroup::Horizon: return run_horizon(s, c.i);
    case CaseGroup::Growth: return run_growth(s, c.i);
  }
  throw std::logic_error("stability: unknown case group");
}

}  // namespace tecido::suites::stability
