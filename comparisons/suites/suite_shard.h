#pragma once
/// Shards of the sweep suites (comparisons/suites/sweep.h) and their merge.
///
/// `tecido suite NAME... --shard i/n --out DIR` computes, for every named sweep suite, only the
/// cases whose index % n == i and writes DIR/shard.json:
///   {"format":"tecido-suite-shard", "shard":[i,n],
///    "settings":{"seed":S, "quick":bool, "data":"dir", "tolerances":{"file":"path","contents":{...}}},
///    "suites":[{"name":"..", "cases":N, "seconds":wall s, "results":[{"index":k,"result":{...}}, ...]}]}
/// one line per case result. The tolerance file's contents travel with the shard, so the merge
/// checks against the very tolerances the shards used.
///
/// `tecido merge DIR...` reads the n shard files and checks that they belong together: the same n,
/// each i in 0..n-1 exactly once, the same settings, the same suites with the same case counts,
/// every case exactly once and in the shard its index belongs to. Any violation is an
/// io::InputError (one line naming the file; the CLI exits 2, nothing written). It then assembles
/// each suite from its cases in index order, which gives the unsharded run's report except for
/// wall-clock fields (a suite's "seconds" is the sum of the shards').
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"

#include <cstddef>
#include <string>
#include <vector>

namespace tecido::suites {

/// One suite's slice in a shard.
struct SuiteSlice {
  std::string name;
  std::size_t cases = 0;               ///< the suite's total case count
  std::vector<std::size_t> indices;    ///< computed here, ascending
  std::vector<io::Json> results;       ///< one per index
  double seconds = 0.0;                ///< wall time of this slice
};

/// The case indices of shard i of n: k % n == i.
std::vector<std::size_t> shard_indices(std::size_t cases, int shard_index, int shard_count);

/// The text of DIR/shard.json for shard i/n of the given slices run under ctx.
std::string suite_shard_json(const std::vector<SuiteSlice>& slices, const SuiteContext& ctx, int shard_index,
                             int shard_count);

/// True when `doc` (a parsed JSON file) is a suite shard rather than another kind of shard.
bool is_suite_shard(const io::Json& doc);

/// What the merge of suite shards gives back: the settings and every suite's results in order.
struct MergedSuites {
  int shards = 0;
  std::uint64_t seed = 0;
  bool quick = false;
  std::string data_dir;
  Tolerances tolerances;
  std::vector<SuiteSlice> suites;  ///< indices 0..cases-1, results in index order; seconds summed
};

/// Reads and checks the shard files (paths of shard.json files); throws io::InputError.
MergedSuites merge_suite_shards(const std::vector<std::string>& files);

}  // namespace tecido::suites
