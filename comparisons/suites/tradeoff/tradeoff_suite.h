#pragma once
/// Suite `tradeoff`: what each bit of accuracy costs. A hanging cloth (curtain.h, n x n nodes) is
/// simulated for the settings' time by every engine in tradeoff_engines() at a few halvings of the
/// step. Each run that counts is a point (cost = wall seconds per simulated second, error = RMS node
/// distance at the end to a converged reference, reference_solution.h), after checking that the
/// scene is well-conditioned. It reports the Pareto front (no other point is both cheaper and more
/// accurate), plots cost against error, and reruns every front point to check that it is
/// bit-for-bit reproducible.
///
/// Layout: settings.h (what runs), curtain.* (the scene), theory.* (the step sweep, the reference's
/// error estimate), engines.* and outside_engines.* (who runs, from the one registry of dynamics
/// engines, comparisons/engines/dynamics_engines.h; outside engines from --plugin and --engine-cmd), reference_solution.* (the untimed runs), cases.* (case indexing
/// and the two case groups), points.* and pareto.* (the cost/error plane and its front),
/// distances.*, size_analysis.*, tradeoff_report.* (tables, data files, plots), findings.* (prose
/// from the tables); this file declares the checks and assembles.
///
/// Checks: per size, conditioning, reference_error, reference_order, front_size and (reference
/// build, sizes the twin runs on) the twin's distance to core's symplectic Euler are declared from
/// the settings before any case runs. The reproducibility checks exist per point of the measured
/// front, so they are declared when the front is known (the one documented exception).
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"
#include "comparisons/suites/tradeoff/engines.h"
#include "comparisons/suites/tradeoff/settings.h"

#include <vector>

namespace tecido::suites {

namespace tradeoff {

/// The checks declared before any case runs (all but the per-front-point ones).
CheckList declare_tradeoff_checks(const Settings& s, const std::vector<TradeoffEngine>& engines, const Tolerances& tol);

}  // namespace tradeoff

/// The suite as a sweep (cases.h): for each cloth size, the untimed runs, then one case per engine
/// and step (a timed run and a rerun for reproducibility; the wall seconds travel in the result).
Sweep tradeoff_sweep(const SuiteContext& ctx);
SuiteResult run_tradeoff_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
