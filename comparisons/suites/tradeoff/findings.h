#pragma once
/// What the `tradeoff` suite's tables show, as prose computed from them: every number and every
/// stated conclusion below is derived from the SizeAnalysis values of the same run.
#include "comparisons/suites/tradeoff/engines.h"
#include "comparisons/suites/tradeoff/settings.h"
#include "comparisons/suites/tradeoff/size_analysis.h"

#include <string>
#include <vector>

namespace tecido::suites::tradeoff {

/// Core's integrators: the first swept step per size, and the largest step at which explicit
/// Euler and midpoint counted on each size.
std::string core_findings(const std::vector<SizeAnalysis>& sizes, const std::vector<TradeoffEngine>& engines);

/// Bullet's engines (a note when none ran): where they run (from the settings); the explicit twin's
/// distance to core's symplectic Euler, its cost against core's and whether it reaches a front; the
/// implicit world's observed order and what more CG iterations do to its error; the classic body's
/// error from the first to the last step it ran and its spread across sweep counts.
std::string bullet_findings(const std::vector<SizeAnalysis>& sizes, const std::vector<TradeoffEngine>& engines,
                            const Settings& s);

}  // namespace tecido::suites::tradeoff
