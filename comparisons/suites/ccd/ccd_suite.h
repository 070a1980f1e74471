#pragma once
/// Suite `ccd`: continuous collision (vertex-face, edge-edge) of every registered engine
/// (comparisons/engines/ccd_engines.h: core, exact, fcl, bullet) and every outside engine
/// answering ccd (--plugin, --engine-cmd; suite_engines.h), as --engines selects, against the exact referee, on
/// the families of the CCD benchmark's handcrafted set and random motion: false negatives,
/// false positives, time-of-impact error and time per query, per engine and family.
/// Checks: core misses nothing and never reports a time after the referee's, on every family;
/// the referee reproduces every constructed answer and agrees with itself without its filter;
/// on random motion, core's false positive share and time error and FCL's and Bullet's miss and
/// false positive shares and late toi (the largest toi - t* where both hit, max_toi_late) stay
/// within their bands. Elsewhere FCL and Bullet are reported, not checked. An outside engine is
/// checked like them, on random motion only, of the kinds it models
/// (/ccd/outside_random_max_fn_rate, _fp_rate, _unanswered_rate, _toi_late); a kind it does not
/// model is reported "not modelled by <engine>". Checks exist only for the engines that run; the
/// sheet-through-sheet group measures core and runs when core does. Disagreements go to
/// DIR/ccd/disagreements.json, which `tecido ccd --queries` re-runs; per engine, the report and
/// stderr give the replay of its own (agreement/replay.h).
///
/// Layout: settings.h (what runs), constructions.* and families.* with vertex_face_families.cpp
/// and edge_edge_families.cpp (the generators), family_case.* (one case: a family through every
/// engine), family_statistics.* (the tallies), disagreements.* (the file), ccd_report.* (tables
/// and conclusions); this file declares the checks and assembles.
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"

namespace tecido::suites {

/// One case per family (comparisons/suites/ccd/families.h), in the table's order; no case
/// without the exact referee (reference build).
Sweep ccd_sweep(const SuiteContext& ctx);
SuiteResult run_ccd_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
