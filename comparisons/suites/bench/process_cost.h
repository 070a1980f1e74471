#pragma once
/// The whole `tecido selfcollide` process timed by the `bench` suite, on the folding cloth of
/// folding_cloth.h written as OBJ: parsing, detection (with --to, core's continuous detection and
/// the exact referee's confirmation) and the JSON output, as a user runs it. The results are rows
/// like tecido-bench's (benchmark_json.h), so the goals are computed from them the same way:
///   process/selfcollide/discrete/<n>                `tecido selfcollide --mesh T1 --json`
///   process/selfcollide/continuous/threads:<t>/<n>  `tecido selfcollide --mesh T0 --to T1 --threads t --json`
/// ns_per_iter is the median over the rounds of the child's CPU time (user + system, all its threads),
/// real_ns_per_iter the median wall time. Counters: `triangles`, `rounds`, and on the continuous rows
/// `same_answer` (1 when the output is byte-identical to the first thread count's, else 0). The rounds
/// run the commands in turn, the order rotating from round to round (a machine growing busier
/// penalises none).
#include "comparisons/suites/bench/benchmark_json.h"

#include <string>
#include <vector>

namespace tecido::suites::bench {

struct ProcessRun {
  std::vector<BenchRow> rows;
  std::vector<std::string> commands;  ///< one per row, as a user would type them (files under `dir`)
  std::string error;                  ///< "" when every command succeeded
};

/// Writes the n x n fold's frames into `dir` and times `tecido` (the binary's path) on them,
/// `rounds` rounds; the continuous command once per entry of `threads` (the first is the reference
/// of `same_answer`). Outputs go to `dir`/<row>.out while compared, then are removed.
ProcessRun time_selfcollide(const std::string& tecido, const std::string& dir, int n, int rounds, const std::vector<int>& threads);

}  // namespace tecido::suites::bench
