#pragma once
/// The `drift` suite's report: its settings, the invariants table and energy plots with what
/// theory says and what this run's table shows, then the Bullet comparisons, each a short function
/// of the values computed in the same run (no measured number is a literal here).
#include "comparisons/suites/drift/invariants.h"
#include "comparisons/suites/drift/settings.h"
#include "comparisons/suites/suite.h"

#include <string>
#include <vector>

namespace tecido::suites::drift {

/// One (scene, integrator) run as the report sees it; `error` is set when its case threw.
struct InvariantRow {
  std::string scene;
  IntegratorKind kind = IntegratorKind::Symplectic;
  InvariantRun run;
  std::string error;
};

/// The settings paragraph (what ran, from Settings).
std::string settings_markdown(const Settings& s);
/// The definitions of the table's columns.
std::string invariants_method(const Settings& s);
/// One table for every row (an unstable run or a case that threw says so in its row).
std::string invariants_table(const std::vector<InvariantRow>& rows);
/// The energy plot of one scene's rows under ctx.out_dir/drift (data file always, SVG with
/// gnuplot); returns the Markdown image link or "".
std::string energy_plot(const SuiteContext& ctx, const std::string& scene, const std::vector<InvariantRow>& rows,
                        std::vector<std::string>& plots);
/// What theory says about each column, then what this run's table shows (ranges computed from `rows`).
std::string invariants_findings(const std::vector<InvariantRow>& rows);

/// The twin paragraph and its plot, from the twin case's result (or its error).
std::string twin_markdown(const SuiteContext& ctx, const Settings& s, const io::Json& result,
                          std::vector<std::string>& plots);
/// The falling paragraph.
std::string falling_markdown(const Settings& s, const io::Json& result);
/// The classic soft body: calibration, the other load, and the finding derived from them.
std::string classic_markdown(const Settings& s, const io::Json& result);
/// The wind paragraph: what each Bullet engine does not model.
std::string wind_markdown(const io::Json& result);

/// "a; b; c", or "nothing (exact twin)" for an empty list.
std::string not_modelled_text(const io::Json& list);

}  // namespace tecido::suites::drift
