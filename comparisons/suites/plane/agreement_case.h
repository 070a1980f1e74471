#pragma once
/// One agreement case of the `plane` suite: the exact referee and every engine on one block of one
/// category's cases (case_index.h), each engine timed over the whole block (CPU time of the thread).
#include "comparisons/engines/segment_plane_engines.h"
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/plane/case_index.h"

#include <cstdint>
#include <vector>

namespace tecido::suites::plane {

/// Generates the cases of `range` (category_case with `seed`), asks `referee` and each of
/// `engines`. Result: comparisons/suites/agreement/block_result.h ("seconds": thread CPU time over
/// the block; "exact path": the calls core's filter left to its exact path; at most
/// `max_disagreements` disagreements). Throws what a generator or an engine throws, and when the
/// referee gives no answer.
io::Json run_agreement_case(std::uint64_t seed, const std::vector<Category>& categories, const CaseRange& range,
                            const SegmentPlaneEngine& referee, const std::vector<SegmentPlaneEngine>& engines,
                            std::size_t max_disagreements);

}  // namespace tecido::suites::plane
