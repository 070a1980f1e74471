#pragma once
/// Outside dynamics engines (--plugin, --engine-cmd) as entries of the `tradeoff` suite, beside
/// core's and Bullet's: timed like them on the same cloths and steps, within Settings::outside's
/// range, taking their steps through their door in chunks (TradeoffEngine::door_chunk). Their cost
/// is the wall time of a run, so it includes the door: a plug-in's calls, and for a process the
/// round trips through its pipes, the JSON both ways and the process's own stepping; the report
/// says so. A cloth the engine refuses is its points' status "not modelled by NAME: why".
///
/// Check per engine and cloth size in its range: `tradeoff/<n>/<engine>/reproducible`, the largest
/// rerun difference (max |x - x_rerun|) over its points that returned positions, within
/// /tradeoff/reproducible_max_abs_diff: the same run twice through the door gives the same nodes.
/// No point with positions (every run refused or failed) fails it with the points' statuses.
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/suites/check.h"
#include "comparisons/suites/tolerances.h"
#include "comparisons/suites/tradeoff/engines.h"
#include "comparisons/suites/tradeoff/settings.h"
#include "comparisons/suites/tradeoff/size_analysis.h"

#include <string>
#include <vector>

namespace tecido::suites::tradeoff {

/// Steps per call of an outside engine's door.
constexpr long long kOutsideChunk = 64;

/// `engine` as a tradeoff engine, named as on the command line, with s.outside's range.
TradeoffEngine outside_tradeoff_engine(const outside::OutsideEnginePtr& engine, const Settings& s);

/// "tradeoff/<n>/<engine>/reproducible"
std::string outside_check_name(int n, const std::string& engine);
/// The check of every outside engine (door set) on every size in its range.
void declare_outside_checks(CheckList& checks, const Settings& s, const std::vector<TradeoffEngine>& engines,
                            const Tolerances& tol);
/// Sets or fails the size's outside checks from its points.
void record_outside_checks(CheckList& checks, const SizeAnalysis& a, const std::vector<TradeoffEngine>& engines);

/// The paragraph naming each outside engine with its door and saying what its cost includes; ""
/// without outside engines.
std::string outside_markdown(const std::vector<TradeoffEngine>& engines);

}  // namespace tecido::suites::tradeoff
