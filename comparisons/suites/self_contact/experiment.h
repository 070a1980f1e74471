#pragma once
/// `tecido experiment self-contact`: the seed's 72-run experiment (section 3.1.3, fig. 21, tables
/// 1-3) replicated as an ensemble, with its claims judged by stated rules (claims.h).
///
/// Layout of this folder (like comparisons/suites/order/): settings.h (what runs), grid.h (the 72
/// cells), interpretation.h and scene_applier.h (a reading of the seed applied to the base Scene),
/// run.h (one run = one case), statistics.h and ensemble.h (summaries, effects), claims.h and
/// timing.h (the claims and their rules), calibration.h (the declared fit), sensitivity.h (the
/// open choices), document.h and report.h (experiment.json, experiment.md, plots), shards.h
/// (--shard and `tecido merge`); this file plans the cases and assembles.
///
/// The cases of a run, in index order (a shard runs those with index % n == i):
///  - with every cell selected: two timing cases (tri-tri tests, phases of a step; timing.h);
///  - for each reading (the baseline, then the sensitivity variants), for each selected cell,
///    for each seed index s < N: one run, wind seed substream(scene seed, s) (so the seeds of one
///    cell are consecutive cases and an ensemble spreads over the shards); a variant that only
///    changes the push (Variant::reuses_none) runs its mode cells only and takes the baseline's
///    no-response runs, which would be the same bytes;
/// and with --calibrate instead: for each grid point, each fit cell, each seed: one run.
/// Results travel as JSON (sweep.h), so an unsharded run and a merge of its shards assemble the
/// same bytes apart from wall-clock fields (the timing cases and the claims decided from them).
#include "comparisons/suites/self_contact/calibration.h"
#include "comparisons/suites/self_contact/sensitivity.h"
#include "comparisons/suites/self_contact/seed_tables.h"
#include "comparisons/suites/self_contact/settings.h"
#include "comparisons/suites/sweep.h"
#include "core/scene/scene.h"

#include <string>
#include <utility>
#include <vector>

namespace tecido::suites::self_contact {

struct Options {
  std::string scene_path, seed_table_path, calibration_path;
  bool quick = false;
  int seeds = 0;                       ///< runs per cell; 0 = the settings' default
  std::vector<std::string> detectors;  ///< counting detectors; empty = core-mt and core (quick: core-mt)
  std::vector<int> cells;              ///< --runs: only these cells, in this order; empty = all 72
  std::string sensitivity = "strength";  ///< the readings of sensitivity.h: none | strength | all (none with --quick)
  bool calibrate = false;              ///< run the calibration instead of the experiment
  std::string elasticity_as;           ///< "" = stiffness (the scene's reading)
  double strength = -1.0;              ///< push [N]; < 0 = the scene's
  // How to run (not part of the result):
  int threads = 1;
  int shard_index = 0, shard_count = 1;
  bool progress = false;
  std::string out_dir;                 ///< where plots go
};

/// One case of the plan.
struct CaseSpec {
  enum Kind { Run, TriTriTiming, PhaseTiming, Calibration } kind = Run;
  int variant = 0;  ///< index into Plan::variants (Run)
  int cell = 0;
  int seed = 0;
  int grid = 0;     ///< grid point (Calibration)
};

/// Everything the cases and the assembly need, read and checked once.
struct Plan {
  Options opt;
  Settings settings;
  Scene base;
  SeedTables seed;
  CalibrationRecord calibration;       ///< (not read with --calibrate)
  Interpretation baseline;             ///< the scene's reading, CLI overrides, calibrated drag and rate
  std::vector<Variant> variants;       ///< baseline first
  std::vector<ContactTest> detectors;
  std::vector<int> cells;
  std::vector<CaseSpec> cases;
  bool all_cells = true;
};

/// Reads the scene, the seed's tables and the calibration record, and lists the cases; throws
/// io::InputError / io::UsageError on bad input or options.
Plan make_plan(const Options& opt);

/// The scene of a Run case: the base scene with the case's cell, its variant's reading and its wind
/// seed applied (scene_applier.h), simulated for Settings::simulated_time.
Scene run_case_scene(const Plan& plan, const CaseSpec& c);

/// The sweep of a plan (its run_case; results as JSON).
Sweep make_sweep(const std::shared_ptr<const Plan>& plan);

/// What the run writes: file name -> contents (experiment.json and .md, or calibration.json and
/// .md); plots are written under opt.out_dir during assembly. `summary` is the line the CLI prints.
struct Outputs {
  std::vector<std::pair<std::string, std::string>> files;
  std::string summary;
};
Outputs assemble(const Plan& plan, const std::vector<io::Json>& results);

/// The command line that reproduces the plan's settings (for records and reports).
std::string command_line(const Options& opt);

}  // namespace tecido::suites::self_contact
