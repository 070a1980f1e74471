#include "comparisons/suites/merge.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/shard_file.h"

#include <fmt/format.h>

#include <cstdint>
#include <limits>
#include <map>

namespace tecido::suites {

namespace {

/// The settings a shard was run with (everything but the runs and the shard position).
SelfContactOptions shard_options(const io::JsonReader& rd, const io::Json& doc) {
  SelfContactOptions opt;
  opt.scene_path = rd.string(rd.require(doc, "", "scene"), "/scene");
  opt.seed_table_path = rd.string(rd.require(doc, "", "seed_table"), "/seed_table");
  opt.simulated_time = rd.number(rd.require(doc, "", "simulated_time"), "/simulated_time");
  opt.quick = rd.boolean(rd.require(doc, "", "quick"), "/quick");
  opt.elasticity_as = rd.string(rd.require(doc, "", "elasticity_as"), "/elasticity_as");
  const io::Json& strength = rd.require(doc, "", "strength");
  if (strength.is_string()) {
    if (strength.get<std::string>() != "scene") rd.fail("/strength", "expected a number or \"scene\"");
    opt.strength = -1.0;
  } else {
    opt.strength = rd.number(strength, "/strength");
  }
  return opt;
}

bool same_settings(const SelfContactOptions& a, const SelfContactOptions& b) {
  return a.scene_path == b.scene_path && a.seed_table_path == b.seed_table_path && a.simulated_time == b.simulated_time &&
         a.quick == b.quick && a.elasticity_as == b.elasticity_as && a.strength == b.strength;
}

}  // namespace

MergedSelfContact merge_self_contact_shards(const std::vector<std::string>& files) {
  if (files.empty()) throw io::UsageError("merge: no shard directory given");
  const auto all_runs = self_contact_runs();
  const int run_count = static_cast<int>(all_runs.size());

  // Read every file; check it is a self-contact shard.
  std::vector<ShardFile> shards;
  for (const auto& file : files) {
    ShardFile s;
    s.file = file;
    s.doc = io::read_json_file(file);
    const io::JsonReader rd(file);
    rd.require_object(s.doc, "");
    if (!s.doc.contains("shard"))
      rd.fail("/shard", "not a shard (written without --shard i/n); only shards can be merged");
    read_shard_position(rd, s);
    const io::Json& experiment = rd.require(s.doc, "", "experiment");
    if (!experiment.is_string() || experiment.get<std::string>() != "self-contact")
      rd.fail("/experiment", "expected \"self-contact\" (the only experiment that can be sharded)");
    shards.push_back(std::move(s));
  }

  // Same n, each shard once, none missing.
  const ShardFile& first = shards.front();
  const int n = first.count;
  const std::vector<const ShardFile*> by_index = shards_by_index(shards);

  // Same settings and selection.
  MergedSelfContact merged;
  merged.shards = n;
  merged.opt = shard_options(io::JsonReader(first.file), first.doc);
  std::vector<int> selection;
  {
    const io::JsonReader rd(first.file);
    const io::Json& sel = rd.require_array(rd.require(first.doc, "", "selection"), "/selection");
    for (std::size_t k = 0; k < sel.size(); ++k)
      selection.push_back(static_cast<int>(rd.integer(sel[k], io::child("/selection", k), 0, run_count - 1)));
  }
  for (const auto& s : shards) {
    const io::JsonReader rd(s.file);
    if (!same_settings(shard_options(rd, s.doc), merged.opt))
      rd.fail("", "run with other settings (scene, seed_table, simulated_time, quick, elasticity_as or strength) than " +
                      first.file);
    if (rd.require(s.doc, "", "selection") != first.doc["selection"])
      rd.fail("/selection", "a different run selection (--runs) than " + first.file);
  }

  // Every selected run exactly once, in its own shard.
  std::map<int, int> wanted;  // run index -> position in the selection
  for (std::size_t k = 0; k < selection.size(); ++k)
    if (!wanted.emplace(selection[k], static_cast<int>(k)).second)
      throw io::InputError(first.file, io::child("/selection", k),
                           fmt::format("run {} is selected twice", selection[k]));
  std::vector<SelfContactResult> results(selection.size());
  std::vector<const ShardFile*> found(selection.size(), nullptr);
  for (const auto& s : shards) {
    const io::JsonReader rd(s.file);
    const io::Json& runs = rd.require_array(rd.require(s.doc, "", "runs"), "/runs");
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const std::string where = io::child("/runs", k);
      const io::Json& j = rd.require_object(runs[k], where);
      const int index = static_cast<int>(rd.integer(rd.require(j, where, "index"), io::child(where, "index"), 0, run_count - 1));
      const auto it = wanted.find(index);
      if (it == wanted.end()) rd.fail(io::child(where, "index"), fmt::format("run {} is not in the selection", index));
      if (index % n != s.index)
        rd.fail(io::child(where, "index"), fmt::format("run {} belongs to shard {}/{}, not {}/{}", index, index % n, n, s.index, n));
      if (found[it->second])
        rd.fail(io::child(where, "index"), fmt::format("run {} appears twice (also in {})", index, found[it->second]->file));
      found[it->second] = &s;

      SelfContactResult r;
      r.run = all_runs[index];
      const io::Json& mode = rd.require(j, where, "mode");
      const int m = mode.is_string() && mode.get<std::string>() == "none"
                        ? 0
                        : static_cast<int>(rd.integer(mode, io::child(where, "mode"), 1, 3));
      if (rd.number(rd.require(j, where, "elasticity"), io::child(where, "elasticity")) != r.run.elasticity ||
          rd.number(rd.require(j, where, "dt"), io::child(where, "dt")) != r.run.dt ||
          rd.number(rd.require(j, where, "wind"), io::child(where, "wind")) != r.run.wind || m != r.run.mode)
        rd.fail(where, fmt::format("elasticity, dt, wind or mode do not match run {}", index));
      const auto count = [&](const char* key) {
        return static_cast<long long>(rd.integer(rd.require(j, where, key), io::child(where, key), 0,
                                                 std::numeric_limits<std::int64_t>::max()));
      };
      r.frames = count("frames");
      r.contact_frames = count("contact_frames");
      r.pairs = count("pairs");
      r.max_pairs = count("max_pairs");
      r.share = rd.number(rd.require(j, where, "share"), io::child(where, "share"));
      r.status = rd.string(rd.require(j, where, "status"), io::child(where, "status"));
      const io::Json& at = rd.require(j, where, "unstable_at_step");
      r.unstable_at_step = at.is_null() ? -1 : count("unstable_at_step");
      results[it->second] = std::move(r);
    }
  }
  for (std::size_t k = 0; k < selection.size(); ++k)
    if (!found[k])
      throw io::InputError(by_index[selection[k] % n]->file, "/runs",
                           fmt::format("run {} is missing (it belongs to shard {}/{})", selection[k], selection[k] % n, n));
  merged.results = std::move(results);
  return merged;
}

}  // namespace tecido::suites
