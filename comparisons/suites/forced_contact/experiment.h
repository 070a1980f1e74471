#pragma once
/// `tecido experiment forced-contact`: the seed's argument for GIA (section 3.1.3, fig. 16) run
/// as an experiment. Moving grips force a folded cloth through itself, hold it for H, then let go
/// (scene.h); for each response and hold an ensemble of runs says whether and when the cloth is
/// free of self-intersection again (run.h, recovery.h), and the seed's claims are judged by
/// rules stated before the data (claims.h).
///
/// Layout of this folder: settings.h (what runs, the rules' constants), scene.h (the scene and
/// its note), run.h (one run = one case), recovery.h (an ensemble's statistics), claims.h,
/// document.h (experiment.json and experiment.md with the plots), shards.h (--shard, merge);
/// this file plans the cases and assembles. The machinery is the self-contact experiment's:
/// sweeps (sweep.h), shard files (experiment_shard.h), claim and verdict types.
///
/// Cases in index order: for each hold, each response, each run index s < N (so one ensemble's
/// runs are consecutive and spread over the shards). Results travel as JSON, so an unsharded run
/// and the merge of its shards assemble the same bytes (no wall-clock field).
#include "comparisons/suites/forced_contact/claims.h"
#include "comparisons/suites/forced_contact/recovery.h"
#include "comparisons/suites/forced_contact/scene.h"
#include "comparisons/suites/forced_contact/settings.h"
#include "comparisons/suites/sweep.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tecido::suites::forced_contact {

struct Options {
  bool quick = false;
  int seeds = 0;  ///< runs per (response, hold); 0 = the settings' default
  // How to run (not part of the result):
  int threads = 1;
  int shard_index = 0, shard_count = 1;
  bool progress = false;
  std::string out_dir;  ///< where plots go
};

struct CaseSpec {
  int hold = 0;      ///< index into Settings::holds
  int response = 0;  ///< index into Settings::responses
  int seed = 0;      ///< run index s
};

struct Plan {
  Options opt;
  Settings settings;
  ForcedScene scene;
  std::vector<CaseSpec> cases;
};

/// Lists the cases; throws io::UsageError on bad options.
Plan make_plan(const Options& opt);
/// The sweep of a plan (its run_case; results as JSON).
Sweep make_sweep(const std::shared_ptr<const Plan>& plan);
/// The case's identity as recorded in its result ("case").
io::Json case_id(const CaseSpec& c);

/// What the assembly found: the runs by (hold, response, s), each ensemble's outcome, the claims.
struct Findings {
  std::vector<RunResult> results;                   ///< per case (default for a case that threw)
  RunTable runs;                                    ///< pointers into results
  std::vector<std::vector<CellOutcome>> outcomes;   ///< [hold][response]
  std::vector<Claim> claims;
  std::vector<std::string> errors;                  ///< "case k threw: ..."
};
Findings find(const Plan& plan, const std::vector<io::Json>& results);

struct Outputs {
  std::vector<std::pair<std::string, std::string>> files;  ///< experiment.json, experiment.md
  std::string summary;
};
Outputs assemble(const Plan& plan, const std::vector<io::Json>& results);

/// The command line that reproduces the plan.
std::string command_line(const Options& opt);

}  // namespace tecido::suites::forced_contact
