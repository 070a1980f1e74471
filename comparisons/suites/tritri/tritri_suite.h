#pragma once
/// Suite `tritri`: every triangle-triangle engine against the exact referee on random pairs and
/// adversarial families, by family, with nanoseconds per random pair.
///
/// An instance of the agreement kit (comparisons/suites/agreement/: family table, blocks, tally,
/// disagreement file, report pieces). Layout: settings.h (what runs), families.* (one generator per
/// family, in a table), case_index.h (pairs into cases), tritri_case.* (one case), check_plan.* (the
/// checks, declared before anything runs), tritri_report.* (tables and prose); this file builds the
/// sweep, assembles, and writes the pairs file of the disagreements.
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/engines/tri_tri_engines.h"
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"
#include "comparisons/suites/tritri/families.h"
#include "comparisons/suites/tritri/settings.h"

#include <vector>

namespace tecido::suites {

/// The suite as a sweep with `settings` over `families`, `engines` and the `outside` engines
/// (answering whole blocks through their doors, checked on every family); the referee is the
/// engine named "exact" (without one, no case runs and no check is declared: the report says so).
/// Case k is case_ranges(...)[k]: every engine on one block of one family.
Sweep tritri_sweep_for(const SuiteContext& ctx, const tritri::Settings& settings, std::vector<tritri::Family> families,
                       std::vector<TriTriEngine> engines, std::vector<outside::OutsideEnginePtr> outside = {});
/// tritri_sweep_for with tritri::settings(ctx.quick), tritri::families(), every registered engine
/// and every outside engine answering tri_tri, those ctx.selects() (the referee always).
Sweep tritri_sweep(const SuiteContext& ctx);
SuiteResult run_tritri_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
