#pragma once
/// Shards of `tecido experiment forced-contact --shard i/n` and their merge (`tecido merge`), in
/// the experiments' shard format (comparisons/suites/experiment_shard.h, "experiment":
/// "forced-contact"): the merge rebuilds the plan from the recorded options and assembles the
/// unsharded run's files.
#include "comparisons/suites/experiment_shard.h"
#include "comparisons/suites/forced_contact/experiment.h"

#include <string>
#include <vector>

namespace tecido::suites::forced_contact {

/// The options that decide the plan, as recorded in a shard.
io::Json options_json(const Options& o);

/// The shard file of `plan` with the results of its cases `indices` (ascending).
std::string shard_json(const Plan& plan, const std::vector<std::size_t>& indices, const std::vector<io::Json>& results);

struct Merged {
  Outputs outputs;
  int shards = 0;
  std::size_t cases = 0;
};
/// Reads and checks the shard files; returns the assembled outputs (plots written to out_dir).
Merged merge_shards(const std::vector<std::string>& files, const std::string& out_dir);

}  // namespace tecido::suites::forced_contact
