#pragma once
/// Joining the shards of a sweep run on several machines (`tecido experiment self-contact
/// --shard i/n`, one output directory each) back into the unsharded result: `tecido merge`.
///
/// Each shard's experiment.json carries {"shard":[i,n], "selection":[run indices], "seed_table"}
/// besides the unsharded fields. The shards must be consistent: the same n, each i in 0..n-1
/// exactly once, the same experiment settings and selection, every selected run exactly once
/// and in the shard its index belongs to (index % n == i). Any violation is an io::InputError
/// (one line; the CLI exits 2). The merged results are in the selection's order, so writing them
/// with self_contact_json / self_contact_markdown gives the unsharded run's files byte for byte.
#include "comparisons/suites/experiment_self_contact.h"

#include <string>
#include <vector>

namespace tecido::suites {

struct MergedSelfContact {
  SelfContactOptions opt;                  ///< the settings the shards were run with
  std::vector<SelfContactResult> results;  ///< every selected run, in the selection's order
  int shards = 0;
};

/// Reads and checks the shard files (paths of experiment.json files).
MergedSelfContact merge_self_contact_shards(const std::vector<std::string>& files);

}  // namespace tecido::suites
