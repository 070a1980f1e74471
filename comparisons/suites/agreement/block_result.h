#pragma once
/// One sweep case of an agreement suite as JSON: the referee's answers and every engine's on one
/// block of one family (case_blocks.h), tallied; and its addition to the AgreementTable. The JSON
/// travels between a sweep case and the assembly (and through shard files), so it is lossless.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/agreement/case_blocks.h"
#include "comparisons/suites/agreement/table.h"

#include <optional>
#include <string>
#include <vector>

namespace tecido::suites::agreement {

/// One engine's answers to a block and what they cost.
struct EngineRun {
  std::string name;
  double seconds = 0.0;  ///< CPU time of the case's thread over the block (and an outside process's round trips)
  std::vector<std::optional<Answer>> answers;
  long exact_path = 0;  ///< calls its filter left to its exact path, where the engine counts them
};

/// {"hits": cases the referee says hit, "engines": [{"name", "seconds", "tally": [cases, agree,
/// false hits, misses, no answer, both hit, exact path], "max_t_error", "disagree": [[k, hit, t,
/// referee's hit, referee's t], ...] (at most `cap`; k offset by `first`)}, ...]}.
io::Json block_result(const std::vector<Answer>& truth, const std::vector<EngineRun>& runs, long first, std::size_t cap);

/// Adds one block's result (block_result(), or {"error": ...}) for the cases of `range`; `random`:
/// the range's family is the random one (its time is summed). std::runtime_error when the result
/// lists other engines than the table, or in another order.
void add_block(AgreementTable& table, const CaseRange& range, bool random, const io::Json& result);

}  // namespace tecido::suites::agreement
