#pragma once
/// One run of `tecido suite`, shared by the command (cmd_suite.cpp) and the Python module's
/// suite() (python/src/suite_call.cpp): the suites named, their context (data, tolerances, seed,
/// threads, engines, outside engines) and the output directory, checked and locked in that order
/// before any suite runs; then the suites in order, a progress line each.
#include "comparisons/engines/outside/outside_engines.h"
#include "comparisons/io/output_dir.h"
#include "comparisons/suites/suite.h"
#include "comparisons/suites/tolerances.h"

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace tecido::cli {

/// What the run is asked (the options of `tecido suite`).
struct SuiteSettings {
  std::vector<std::string> names;  ///< suite names, or "all"
  std::string out = "out";
  std::string tolerances;  ///< "": data/tolerances.json
  std::string data;        ///< "": the source tree's data/
  bool quick = false;
  std::uint64_t seed = 20141;
  int threads = 0;          ///< 0: every core
  std::string engines;      ///< comma-separated names; "": every engine
  bool sharded = false;     ///< --shard given (chooses the sweep suites of `all`)
  bool progress = true;     ///< sweep suites draw a progress bar on a terminal
};

class SuiteSession {
 public:
  using LoadOutside = std::function<std::shared_ptr<outside::OutsideEngines>()>;
  /// Chooses the suites (io::UsageError on an unknown name), loads the tolerances, checks and locks
  /// the output directory, then calls `load_outside` (the outside engines; an empty set when none)
  /// and checks --engines against the built-in and outside names.
  SuiteSession(const SuiteSettings& settings, const LoadOutside& load_outside);

  const suites::SuiteContext& context() const { return ctx_; }
  const std::vector<const suites::SuiteEntry*>& chosen() const { return chosen_; }
  /// The suites `all --shard` skipped (not split into cases), comma-separated; "" for none.
  const std::string& skipped() const { return skipped_; }

  /// Runs the chosen suites in order, "suite NAME ... P passed, F failed (S s)" on `log` for each,
  /// and returns their results (the report is not written: suites::write_report).
  std::vector<suites::SuiteResult> run(std::ostream& log) const;

 private:
  std::vector<const suites::SuiteEntry*> chosen_;
  std::string skipped_;
  suites::Tolerances tolerances_;
  suites::SuiteContext ctx_;
  std::unique_ptr<io::OutputDirLock> lock_;
};

}  // namespace tecido::cli
