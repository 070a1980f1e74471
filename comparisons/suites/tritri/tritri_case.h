#pragma once
/// One case of the `tritri` suite: the exact referee and every engine on one block of one
/// family's pairs (case_index.h), each engine timed over the whole block (CPU time of the thread).
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/engines/tri_tri_engines.h"
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/tritri/case_index.h"

#include <cstdint>
#include <vector>

namespace tecido::suites::tritri {

/// Generates the pairs of `range` (families.h: family_pair with `seed`), asks `referee`, each of
/// `engines`, then each of `outside` (the whole block in one batch through its door). Result:
/// comparisons/suites/agreement/block_result.h ("hits": pairs the referee says intersect), each
/// engine's "seconds" the thread's CPU time over the block (for a process engine, plus the wall
/// time of its round trips: its work is not this thread's, and the door is part of its cost).
/// Throws what a generator or an engine throws.
io::Json run_tritri_case(std::uint64_t seed, const std::vector<Family>& families, const CaseRange& range,
                         const TriTriEngine& referee, const std::vector<TriTriEngine>& engines,
                         std::size_t max_disagreements, const std::vector<outside::OutsideEnginePtr>& outside = {});

}  // namespace tecido::suites::tritri
