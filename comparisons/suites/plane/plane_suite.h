#pragma once
/// Suite `plane`: segment versus bounded plane, statically (random and adversarial categories of
/// cases, every registered engine against the exact referee) and dynamically (particles dropped on
/// a floor: the bisected time of contact against the analytic root, by step and by bisection
/// tolerance; and one drop in core and in Bullet, contact time and rebound apex against theory).
///
/// Its static part is an instance of the agreement kit (comparisons/suites/agreement/: family table,
/// blocks, tally, disagreement file, report pieces). Layout: settings.h (what runs), theory.*
/// (contact time, rebound apex), categories.* (one generator per category, in a table),
/// case_index.* (the cases of the sweep), agreement_case.* (one block of cases), group_tally.* (the
/// statistics per group of categories), check_plan.* (the checks, declared before anything runs),
/// contact_time.* and drop.* (the two dynamic groups), plane_report.*, contact_time_report.* and
/// drop_report.* (tables and prose); this file makes the plan, the sweep, assembles, and writes the
/// cases file of the disagreements.
#include "comparisons/engines/segment_plane_engines.h"
#include "comparisons/suites/check.h"
#include "comparisons/suites/plane/case_index.h"
#include "comparisons/suites/plane/categories.h"
#include "comparisons/suites/plane/settings.h"
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace tecido::suites::plane {

/// Everything fixed before a case runs.
struct Plan {
  Settings settings;
  std::uint64_t seed = 0;       ///< the run's seed: the drops of the contact-time group derive from it
  std::uint64_t case_seed = 0;  ///< of the agreement cases: substream(seed, 1)
  std::vector<Category> categories;
  std::optional<SegmentPlaneEngine> referee;  ///< the engine named "exact", when built in
  std::vector<SegmentPlaneEngine> engines;    ///< every other engine, in registry order
  bool bullet = true;                         ///< the drop group runs Bullet
  Layout layout;
  CheckList checks;
};

/// Builds the plan from the context, reading every band from ctx.tolerances (io::InputError when
/// one is missing) and declaring every check.
Plan make_plan(const SuiteContext& ctx, Settings s, std::vector<Category> categories,
               const std::vector<SegmentPlaneEngine>& engines);

/// Runs case k of the plan (case_index.h).
io::Json run_case(const Plan& plan, std::size_t k);

/// Every case's result (index order) into the suite's checks, Markdown and data; writes
/// plane/disagreements.json and plane/contact_time.dat under out_dir. A case that threw fails the
/// checks it feeds with its message; a missing value fails its check with the reason.
SuiteResult assemble(const Plan& plan, const std::string& out_dir, const std::vector<io::Json>& results);

}  // namespace tecido::suites::plane

namespace tecido::suites {

/// The suite as a sweep with `settings` over `categories` and `engines` (the referee is the one
/// named "exact"; without it no agreement case runs and no agreement check is declared).
Sweep plane_sweep_for(const SuiteContext& ctx, plane::Settings settings, std::vector<plane::Category> categories,
                      const std::vector<SegmentPlaneEngine>& engines);
/// plane_sweep_for with plane::settings(ctx.quick), plane::categories() and every registered engine.
Sweep plane_sweep(const SuiteContext& ctx);
SuiteResult run_plane_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
