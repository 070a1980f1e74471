#pragma once
/// The engines the ccd suite runs besides its referee: the built-in ones (ccd_engines.h: core,
/// fcl, bullet) and the outside engines answering ccd (--plugin, --engine-cmd), each kept when
/// --engines selects it (every one when --engines is not given). The exact referee always runs.
#include "comparisons/engines/ccd_engines.h"
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/suites/ccd/constructions.h"
#include "comparisons/suites/suite.h"

#include <optional>
#include <string>
#include <vector>

namespace tecido::suites::ccd {

struct SuiteEngine {
  std::string name;
  const CcdEngine* builtin = nullptr;  ///< null for an outside engine
  outside::OutsideEnginePtr outside;   ///< null for a built-in engine
  /// Whether the engine answers queries of `kind` at all (an outside engine's capabilities; a
  /// built-in engine is asked and may answer null, as bullet does on edge-edge).
  bool models(CcdKind kind) const;
  bool is_outside() const { return outside != nullptr; }
};

/// The built-in engines in their registry's order (core, exact, fcl, bullet; exact always, the
/// others when selected), then the selected outside engines answering ccd, in load order.
std::vector<SuiteEngine> suite_engines(const SuiteContext& ctx);

/// Engine `e`'s answers to a block of queries and what they cost [s]: a built-in engine's wall
/// time over the block; an outside engine gets the block in one batch through its door and costs
/// this thread's CPU time plus the wall time of its own round trips (a process works outside this
/// thread). nullopt where the engine cannot answer, or does not model the query's kind.
std::vector<std::optional<CcdAnswer>> answer_block(const SuiteEngine& e, const std::vector<KnownQuery>& queries,
                                                   double& seconds);

}  // namespace tecido::suites::ccd
