#pragma once
/// Suite `order`: the observed global error order of each dynamics engine on problems with
/// analytic solutions (harmonic oscillator, damped oscillator, projectile with linear drag, two
/// free particles joined by a spring), by step halving, with a slope fitted over the asymptotic
/// range the suite finds itself (order_fit.h), checked against the order each engine claims; and
/// the seed's own question, Euler versus midpoint at equal step and at equal cost.
///
/// Layout: settings.h (what runs), problems.* (the exact solutions), order_engines.* (who runs),
/// convergence.* (one case: an engine on a problem at every step), order_fit.* (the fit),
/// order_report.* (tables, plots, prose); this file declares the checks and assembles.
#include "comparisons/suites/order/order_engines.h"
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"

namespace tecido::suites {

/// The suite as a sweep: one case per (problem, engine), problem-major, for `engines`.
Sweep order_sweep_for(const SuiteContext& ctx, std::vector<order::OrderEngine> engines);
/// order_sweep_for with core's four integrators.
Sweep order_sweep(const SuiteContext& ctx);
SuiteResult run_order_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
