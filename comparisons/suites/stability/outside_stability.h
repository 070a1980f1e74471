#pragma once
/// Outside dynamics engines in the `stability` suite: the largest stable step of the oscillator
/// (oscillator.h: a particle on a zero-rest-length spring to a pinned particle, released at rest
/// 1 m out) on each cell of OutsideSettings' grid, found by the suite's bisection. One case per
/// (engine, cell), after the suite's own cases. Each run advances one period per call of the door
/// and is stable while finite and within the amplitude bound at the end of every period.
///
/// Check per engine: `stability/<engine>/grid_spread` = max/min - 1 of h_max omega over the cells,
/// at most /stability/grid_spread (as core's integrators): the oscillator's dynamics depend on h
/// omega only, so a fixed-step engine that treats stiffness and mass right finds the same h omega
/// everywhere. A cell without a stable step, a refused scene or a failed run fails it with the reason.
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/check.h"
#include "comparisons/suites/stability/oscillator.h"
#include "comparisons/suites/stability/settings.h"
#include "comparisons/suites/tolerances.h"

#include <string>
#include <vector>

namespace tecido::suites::stability {

/// The outside engines the suite runs, and the cells.
struct OutsidePlan {
  std::vector<outside::OutsideEnginePtr> engines;
  OutsideSettings settings;
  double amplitude_bound = 1000.0;
  double rel_tol = 1e-6;
  std::size_t cells() const { return settings.stiffnesses.size() * settings.masses.size(); }
  std::size_t cases() const { return engines.size() * cells(); }
};

OutsidePlan outside_plan(const Settings& s, std::vector<outside::OutsideEnginePtr> engines);

/// One run of `engine` on the oscillator (ks, m) at step h: finite and bounded at every period's end.
bool outside_stable(outside::OutsideEngine& engine, double ks, double m, double h, double periods, double bound);

/// Case i (engine-major, then stiffness, then mass): a StableStep as step_json (cases.h).
io::Json run_outside_case(const OutsidePlan& plan, std::size_t i);

/// "stability/<engine>/grid_spread"
std::string outside_check_name(const std::string& engine);
void declare_outside_checks(CheckList& checks, const OutsidePlan& plan, const Tolerances& tol);

/// The outside cases' results (in case order) into their checks, a table of h_max omega per engine
/// and cell, and report data; "" when there is no outside engine.
std::string outside_tables(const OutsidePlan& plan, const std::vector<io::Json>& results, CheckList& checks,
                           io::Json& data);

}  // namespace tecido::suites::stability
