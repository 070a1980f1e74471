#pragma once
/// Shards of the experiments (`tecido experiment NAME --shard i/n`), shared by every experiment
/// (self_contact/shards.h, forced_contact/shards.h). A shard file is
///   {"format":"tecido-experiment-shard", "experiment":NAME, "shard":[i,n], "tecido":{..},
///    "options":{..the options that decide the plan..}, "cases":N,
///    "results":[{"index":k,"result":{..}}, ...]}   (one line per case)
/// Reading checks that the files belong together (one format, one experiment, the same n and
/// options, each shard once); collecting checks every case once, in its own shard, and the case
/// the plan says. Any violation is an io::InputError (one line; the CLI exits 2).
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/shard_file.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace tecido::suites {

/// The text of a shard file of experiment `name` (results of the cases `indices`, ascending).
std::string experiment_shard_json(const std::string& name, int shard_index, int shard_count, const io::Json& options,
                                  std::size_t cases, const std::vector<std::size_t>& indices,
                                  const std::vector<io::Json>& results);

/// True when `doc` is an experiment shard.
bool is_experiment_shard(const io::Json& doc);
/// The experiment a shard belongs to ("self-contact" when the shard predates the field).
std::string shard_experiment(const io::Json& doc);

/// Reads the shard files of experiment `name` and checks that they are one whole sharding with
/// the same options (the first file's, returned in shards.front().doc["options"]).
std::vector<ShardFile> read_experiment_shards(const std::vector<std::string>& files, const std::string& name);

/// The results of all `cases`, in index order, after checking the shards' case count and that
/// every case appears once, in its own shard, as the result of the case `case_id(k)` says
/// (compared with the result's "case" field).
std::vector<io::Json> collect_experiment_results(const std::vector<ShardFile>& shards, std::size_t cases,
                                                 const std::function<io::Json(std::size_t)>& case_id);

}  // namespace tecido::suites
