#pragma once
/// The comparison suites: each is a name and a function that runs its cases and returns its
/// declared checks (check.h: value against a [lo, hi] band read from the tolerance file), a Markdown
/// section and any plots it wrote. `tecido suite` runs them and writes report.json and report.md.
#include "comparisons/suites/check.h"
#include "comparisons/suites/tolerances.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tecido::outside {
class OutsideEngines;
}

namespace tecido::suites {

struct SuiteContext {
  std::string out_dir;     ///< where plots and side files go
  std::string data_dir;    ///< data/ (scenes, tables)
  bool quick = false;      ///< smaller counts, same checks
  std::uint64_t seed = 0;  ///< every random input derives from this
  int threads = 1;
  const Tolerances* tolerances = nullptr;
  bool gnuplot = false;    ///< gnuplot found on PATH
  bool progress = false;   ///< sweep suites draw a progress bar on stderr (only on a terminal)
  /// Engines from outside tecido's tree (--plugin, --engine-cmd), run beside the built-in ones by
  /// the suites that can use them; null: none.
  std::shared_ptr<const outside::OutsideEngines> outside;
  /// --engines: the engines the suites run, by name; empty: every engine of every suite. A suite
  /// runs the named ones it knows (its referee always runs).
  std::vector<std::string> engines;
  /// Whether `name` is among --engines (always true when --engines was not given).
  bool selects(const std::string& name) const {
    if (engines.empty()) return true;
    for (const auto& e : engines)
      if (e == name) return true;
    return false;
  }
};

/// A page a suite wrote under out_dir (a 3-D view of its disagreements, comparisons/view/):
/// report.html links to it. `href` is relative to out_dir ("ccd/disagreements.html#3").
struct PageLink {
  std::string text;
  std::string href;
};

struct SuiteResult {
  std::string name;
  std::vector<Check> checks;
  std::string markdown;            ///< the suite's section of report.md (tables, plot links)
  std::vector<std::string> plots;  ///< file names written under out_dir
  io::Json data = io::Json::object();  ///< extra machine-readable results for report.json
  std::vector<PageLink> views;     ///< its pages for report.html (not in report.md or report.json)
  double seconds = 0.0;            ///< wall time (not part of the determinism promise)
  /// Lines `tecido suite` prints on stderr under the suite's count of checks: an agreement suite's
  /// disagreements per engine, their first ids, the file holding them all and the replay command
  /// (agreement/replay.h). Not in the report.
  std::vector<std::string> stderr_lines;
};

using SuiteFn = std::function<SuiteResult(const SuiteContext&)>;
struct Sweep;
using SweepFn = std::function<Sweep(const SuiteContext&)>;

struct SuiteEntry {
  std::string name;
  std::string summary;
  SuiteFn run;
  /// Set for a suite split into cases (comparisons/suites/sweep.h): `run` runs them on ctx.threads
  /// threads; `tecido suite --shard i/n` runs a slice and `tecido merge` assembles the slices.
  SweepFn sweep = nullptr;
};

/// Every registered suite in the order `all` runs them.
const std::vector<SuiteEntry>& suite_registry();

/// Runs one suite: its result, named after the entry, with its wall time in `seconds`.
SuiteResult run_suite(const SuiteEntry& entry, const SuiteContext& ctx);

}  // namespace tecido::suites
