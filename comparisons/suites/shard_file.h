#pragma once
/// One shard's file as `tecido merge` reads it, and the check that a set of them is one whole
/// sharding: shared by the experiment merge (merge.h) and the suite merge (suite_shard.h).
#include "comparisons/io/json_reader.h"

#include <string>
#include <vector>

namespace tecido::suites {

struct ShardFile {
  std::string file;
  io::Json doc;
  int index = 0, count = 0;  ///< shard index / shard count, from "/shard": [i, n]
};

/// Sets s.index and s.count from s.doc's "/shard": [i, n] with n >= 1 and 0 <= i < n; throws
/// io::InputError (via rd) naming the path otherwise. s.doc must contain "shard".
void read_shard_position(const io::JsonReader& rd, ShardFile& s);

/// The shards ordered by index, after checking that they are the n shards of one sharding: the
/// same n, each index once, none missing. Throws io::InputError naming the offending file.
std::vector<const ShardFile*> shards_by_index(const std::vector<ShardFile>& shards);

}  // namespace tecido::suites
