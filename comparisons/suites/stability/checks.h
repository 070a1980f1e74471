#pragma once
/// The `stability` suite's checks, declared from its settings before any case runs. Their names
/// depend on the settings alone (which integrators, which groups of extremes); their bands come
/// from the tolerance file's /stability section, which holds nothing else.
#include "comparisons/suites/check.h"
#include "comparisons/suites/stability/extremes.h"
#include "comparisons/suites/stability/settings.h"
#include "comparisons/suites/tolerances.h"

#include <string>
#include <vector>

namespace tecido::suites::stability {

/// "stability/<integrator>/<what>"
std::string check_name(IntegratorKind k, const std::string& what);

/// Every check: per bounded integrator h_omega_ratio_min, h_omega_ratio_max, grid_spread; per grower
/// growth_rel_error, horizon_ratio_min, horizon_ratio_max; then each group's (ExtremeGroup::checks).
/// Throws io::InputError naming the tolerance file when a band is missing.
CheckList declare_checks(const Settings& s, const std::vector<ExtremeGroup>& groups, const Tolerances& tol);

}  // namespace tecido::suites::stability
