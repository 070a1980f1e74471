#pragma once
/// Suite `stability`: the largest stable step of each integrator on an undamped oscillator, found by
/// a deterministic bisection on h, across six decades of stiffness and of mass, against the
/// linear-stability theory (symplectic Euler: h omega < 2; RK4: h omega < 2 sqrt 2; explicit Euler
/// and midpoint: no stable step at all, so their measured growth per period is reported instead);
/// then the extremes: coordinates offset by 1e6..1e8 m, mass ratios of 1e6 across a spring,
/// near-zero rest lengths, a particle resting on a plane for 1e5 steps, and steps of up to 10 s
/// toward a thin bounded plane.
///
/// Layout: settings.h (what runs, including the definition of "stable at h"), theory.* (the
/// predicted values), oscillator.* (the runs and the bisection), one file per group of extremes
/// (offset, mass_ratio, near_zero, resting, tunnelling; extremes.* their common result), cases.*
/// (the case index and table), checks.* (the declared checks), value_range.* (min/max that keep a
/// missing value), tables.* (the tables from the case results), outside_stability.* (outside
/// dynamics engines from --plugin and --engine-cmd, their cases after the suite's own),
/// stability_report.* and extremes_notes.* (the prose); this file makes the plan, the sweep and
/// assembles.
#include "comparisons/suites/check.h"
#include "comparisons/suites/stability/cases.h"
#include "comparisons/suites/stability/extremes.h"
#include "comparisons/suites/stability/outside_stability.h"
#include "comparisons/suites/stability/settings.h"
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"

#include <vector>

namespace tecido::suites::stability {

/// Everything fixed before a case runs: the settings, the groups of extremes, the case layout, the
/// declared checks and the bands of the judged verdicts.
struct Plan {
  Settings settings;
  std::vector<ExtremeGroup> groups;
  Layout layout;
  CheckList checks;
  VerdictBands bands;
  OutsidePlan outside;  ///< outside dynamics engines: their cases follow the layout's
};
/// Reads every band from ctx.tolerances (io::InputError when one is missing) and declares the checks;
/// the outside dynamics engines of ctx that ctx.selects() join after the suite's own cases.
Plan make_plan(const SuiteContext& ctx, Settings s, std::vector<ExtremeGroup> groups);

/// Every case's result (index order) into the suite's checks, Markdown and data. A case that threw
/// fails the checks it feeds with its message; a grid cell without a value fails the grid's checks
/// with a reason naming the cell.
SuiteResult assemble(const Plan& plan, const std::vector<io::Json>& results);

}  // namespace tecido::suites::stability

namespace tecido::suites {

/// The suite as a sweep over `groups` of extremes and the cases of `s` (cases.h gives the order).
Sweep stability_sweep_for(const SuiteContext& ctx, stability::Settings s, std::vector<stability::ExtremeGroup> groups);
/// stability_sweep_for with settings(ctx.quick) and every group of extremes.
Sweep stability_sweep(const SuiteContext& ctx);
SuiteResult run_stability_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
