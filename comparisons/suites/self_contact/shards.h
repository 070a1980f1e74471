#pragma once
/// Shards of the self-contact experiment (`tecido experiment self-contact --shard i/n`) and their
/// merge (`tecido merge`). A shard runs the plan's cases whose index % n == i and writes
/// DIR/experiment.json (DIR/calibration.json with --calibrate) as
///   {"format":"tecido-experiment-shard", "experiment":"self-contact", "shard":[i,n],
///    "options":{..the options that decide the plan..}, "cases":N,
///    "results":[{"index":k,"result":{..}}, ...]}   (one line per case)
/// The merge checks that the shards belong together (one format, the same n and options, each
/// shard once, every case once and in its own shard, each result the case the plan says),
/// rebuilds the plan from the options (so the scene, the seed's tables and the calibration record
/// are read again from the recorded paths) and assembles: the unsharded run's files, apart from
/// wall-clock fields. Any violation is an io::InputError (one line; the CLI exits 2).
#include "comparisons/suites/experiment_shard.h"
#include "comparisons/suites/self_contact/experiment.h"

#include <string>
#include <vector>

namespace tecido::suites::self_contact {

/// The options as recorded in a shard, and back (out_dir, threads, shard and progress are not
/// recorded; the reader sets them to defaults). Throws io::InputError via `rd` on a bad value.
io::Json options_json(const Options& o);
Options options_from_json(const io::JsonReader& rd, const io::Json& j, const std::string& where);

/// The shard file of `plan` with the results of its cases `indices` (ascending).
std::string shard_json(const Plan& plan, const std::vector<std::size_t>& indices, const std::vector<io::Json>& results);

/// (The shard format, its reading and the case checks: comparisons/suites/experiment_shard.h.)

/// Reads and checks the shard files; returns the assembled outputs (plots written to out_dir).
/// A non-empty `seed_table` replaces the seed's tables' path the shards recorded.
struct Merged {
  Outputs outputs;
  int shards = 0;
  std::size_t cases = 0;
};
Merged merge_shards(const std::vector<std::string>& files, const std::string& out_dir, const std::string& seed_table);

}  // namespace tecido::suites::self_contact
