#pragma once
/// Extremes, group "mass ratio": a free pair at equal masses and at heavy : light, and the chain
/// anchor - heavy - light (MassRatioSettings), each with the bounded integrators. Their largest
/// stable step, found by the grid's bisection and definition of "stable at h", against the theory's
/// limit over omega_max (theory.h: pair_omega_max, chain_omega_max).
#include "comparisons/suites/stability/extremes.h"

namespace tecido::suites::stability {

/// stability/extremes/mass_ratio_min and _max: h_max omega_max / limit, over systems and integrators.
std::vector<CheckSpec> mass_ratio_checks(const Settings& s);
/// One row per system; data["mass_ratio"][system][integrator] = {found, omega_max, reference (the
/// equal-mass pair), and when found
/// h_max, ratio (h_max omega_max / limit), smaller_than_equal (the equal-mass pair's h_max / h_max)}.
ExtremeResult run_mass_ratio(const Settings& s);

}  // namespace tecido::suites::stability
