#include "comparisons/suites/experiment_shard.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/provenance.h"
#include "comparisons/suites/sweep.h"

#include <fmt/format.h>

#include <limits>

namespace tecido::suites {

namespace {

constexpr const char* kExperimentFormat = "tecido-experiment-shard";

ShardFile read_experiment_shard(const std::string& file, const std::string& name) {
  ShardFile s;
  s.file = file;
  s.doc = io::read_json_file(file);
  const io::JsonReader rd(file);
  rd.require_object(s.doc, "");
  if (!is_experiment_shard(s.doc))
    rd.fail("/format",
            std::string("not an experiment shard (written without --shard i/n?); expected \"") + kExperimentFormat + "\"");
  if (shard_experiment(s.doc) != name)
    rd.fail("/experiment", "a shard of experiment \"" + shard_experiment(s.doc) + "\", not \"" + name + "\"");
  rd.require(s.doc, "", "shard");
  read_shard_position(rd, s);
  return s;
}

}  // namespace

std::string experiment_shard_json(const std::string& name, int shard_index, int shard_count, const io::Json& options,
                                  std::size_t cases, const std::vector<std::size_t>& indices,
                                  const std::vector<io::Json>& results) {
  std::string out = "{\n\"format\": " + io::Json(kExperimentFormat).dump() + ",\n\"experiment\": " + io::Json(name).dump() +
                    ",\n\"shard\": " + io::Json::array({shard_index, shard_count}).dump() +
                    ",\n\"tecido\": " + io::provenance_json().dump() + ",\n\"options\": " + options.dump() +
                    fmt::format(",\n\"cases\": {},\n\"results\": [", cases);
  for (std::size_t k = 0; k < indices.size(); ++k)
    out += (k ? ",\n" : "\n") + io::Json{{"index", indices[k]}, {"result", results[k]}}.dump();
  return out + "\n]\n}\n";
}

bool is_experiment_shard(const io::Json& doc) {
  return doc.is_object() && doc.contains("format") && doc["format"] == kExperimentFormat;
}

std::string shard_experiment(const io::Json& doc) {
  if (!doc.is_object() || !doc.contains("experiment") || !doc["experiment"].is_string()) return "self-contact";
  return doc["experiment"].get<std::string>();
}

std::vector<ShardFile> read_experiment_shards(const std::vector<std::string>& files, const std::string& name) {
  if (files.empty()) throw io::UsageError("merge: no shard directory given");
  std::vector<ShardFile> shards;
  for (const auto& f : files) shards.push_back(read_experiment_shard(f, name));
  shards_by_index(shards);  // the same n, each shard once, none missing
  const ShardFile& first = shards.front();
  for (const ShardFile& s : shards)
    if (io::JsonReader(s.file).require(s.doc, "", "options") != first.doc["options"])
      io::JsonReader(s.file).fail("/options", "run with other settings (options) than " + first.file);
  return shards;
}

std::vector<io::Json> collect_experiment_results(const std::vector<ShardFile>& shards, std::size_t cases,
                                                 const std::function<io::Json(std::size_t)>& case_id) {
  const int n = shards.front().count;
  for (const ShardFile& s : shards) {
    const io::JsonReader rd(s.file);
    if (rd.integer(rd.require(s.doc, "", "cases"), "/cases", 0, std::numeric_limits<std::int64_t>::max()) !=
        static_cast<std::int64_t>(cases))
      rd.fail("/cases", fmt::format("the shards have a different case count than this build's plan ({})", cases));
  }
  std::vector<io::Json> results(cases);
  std::vector<const ShardFile*> from(cases, nullptr);
  for (const ShardFile& s : shards) {
    const io::JsonReader rd(s.file);
    const io::Json& rs = rd.require_array(rd.require(s.doc, "", "results"), "/results");
    for (std::size_t k = 0; k < rs.size(); ++k) {
      const std::string where = io::child("/results", k);
      rd.require_object(rs[k], where);
      const auto index = static_cast<std::size_t>(
          rd.integer(rd.require(rs[k], where, "index"), io::child(where, "index"), 0, static_cast<std::int64_t>(cases) - 1));
      if (static_cast<int>(index % n) != s.index)
        rd.fail(io::child(where, "index"), fmt::format("case {} belongs to shard {}/{}, not {}/{}", index, index % n, n, s.index, n));
      if (from[index]) rd.fail(io::child(where, "index"), fmt::format("case {} appears twice (also in {})", index, from[index]->file));
      const io::Json& result = rd.require(rs[k], where, "result");
      if (!case_error(result) && (!result.is_object() || !result.contains("case") || result["case"] != case_id(index)))
        rd.fail(io::child(where, "result"), fmt::format("is not the result of case {} of this plan", index));
      from[index] = &s;
      results[index] = result;
    }
  }
  for (std::size_t k = 0; k < results.size(); ++k)
    if (!from[k])
      throw io::InputError(shards.front().file, "/results", fmt::format("case {} is missing (it belongs to shard {}/{})", k, k % n, n));
  return results;
}

}  // namespace tecido::suites
