#include "comparisons/suites/self_contact/shards.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/provenance.h"
#include "comparisons/suites/shard_file.h"

#include <fmt/format.h>

#include <limits>

namespace tecido::suites::self_contact {

namespace {

constexpr const char* kFormat = "tecido-experiment-shard";

std::vector<std::string> strings(const io::JsonReader& rd, const io::Json& j, const std::string& where) {
  std::vector<std::string> out;
  const io::Json& a = rd.require_array(j, where);
  for (std::size_t k = 0; k < a.size(); ++k) out.push_back(rd.string(a[k], io::child(where, k)));
  return out;
}

ShardFile read_shard(const std::string& file) {
  ShardFile s;
  s.file = file;
  s.doc = io::read_json_file(file);
  const io::JsonReader rd(file);
  rd.require_object(s.doc, "");
  if (!is_experiment_shard(s.doc))
    rd.fail("/format", std::string("not an experiment shard (written without --shard i/n?); expected \"") + kFormat + "\"");
  rd.require(s.doc, "", "shard");
  read_shard_position(rd, s);
  return s;
}

/// Puts each shard's results into their slots; every case once, in its own shard, the case the plan says.
std::vector<io::Json> collect(const Plan& plan, const std::vector<ShardFile>& shards, int n) {
  std::vector<io::Json> results(plan.cases.size());
  std::vector<const ShardFile*> from(plan.cases.size(), nullptr);
  for (const ShardFile& s : shards) {
    const io::JsonReader rd(s.file);
    const io::Json& rs = rd.require_array(rd.require(s.doc, "", "results"), "/results");
    for (std::size_t k = 0; k < rs.size(); ++k) {
      const std::string where = io::child("/results", k);
      rd.require_object(rs[k], where);
      const auto index = static_cast<std::size_t>(
          rd.integer(rd.require(rs[k], where, "index"), io::child(where, "index"), 0, static_cast<std::int64_t>(plan.cases.size()) - 1));
      if (static_cast<int>(index % n) != s.index)
        rd.fail(io::child(where, "index"), fmt::format("case {} belongs to shard {}/{}, not {}/{}", index, index % n, n, s.index, n));
      if (from[index]) rd.fail(io::child(where, "index"), fmt::format("case {} appears twice (also in {})", index, from[index]->file));
      const io::Json& result = rd.require(rs[k], where, "result");
      const CaseSpec& c = plan.cases[index];
      const io::Json want = {static_cast<int>(c.kind), c.variant, c.cell, c.seed, c.grid};
      if (!case_error(result) && (!result.is_object() || !result.contains("case") || result["case"] != want))
        rd.fail(io::child(where, "result"), fmt::format("is not the result of case {} of this plan", index));
      from[index] = &s;
      results[index] = result;
    }
  }
  for (std::size_t k = 0; k < results.size(); ++k)
    if (!from[k])
      throw io::InputError(shards.front().file, "/results",
                           fmt::format("case {} is missing (it belongs to shard {}/{})", k, k % n, n));
  return results;
}

}  // namespace

io::Json options_json(const Options& o) {
  return {{"scene", o.scene_path},        {"seed_table", o.seed_table_path}, {"calibration", o.calibration_path},
          {"quick", o.quick},             {"seeds", o.seeds},                {"detectors", o.detectors},
          {"runs", o.cells},              {"sensitivity", o.sensitivity},    {"calibrate", o.calibrate},
          {"elasticity_as", o.elasticity_as}, {"strength", o.strength}};
}

Options options_from_json(const io::JsonReader& rd, const io::Json& j, const std::string& w) {
  rd.require_object(j, w);
  Options o;
  o.scene_path = rd.string(rd.require(j, w, "scene"), io::child(w, "scene"));
  o.seed_table_path = rd.string(rd.require(j, w, "seed_table"), io::child(w, "seed_table"));
  o.calibration_path = rd.string(rd.require(j, w, "calibration"), io::child(w, "calibration"));
  o.quick = rd.boolean(rd.require(j, w, "quick"), io::child(w, "quick"));
  o.seeds = static_cast<int>(rd.integer(rd.require(j, w, "seeds"), io::child(w, "seeds"), 0, 1000000));
  o.detectors = strings(rd, rd.require(j, w, "detectors"), io::child(w, "detectors"));
  const io::Json& runs = rd.require_array(rd.require(j, w, "runs"), io::child(w, "runs"));
  for (std::size_t k = 0; k < runs.size(); ++k)
    o.cells.push_back(static_cast<int>(rd.integer(runs[k], io::child(io::child(w, "runs"), k), 0, CellGrid::kCells - 1)));
  o.sensitivity = rd.string(rd.require(j, w, "sensitivity"), io::child(w, "sensitivity"));
  if (!is_sensitivity_set(o.sensitivity)) rd.fail(io::child(w, "sensitivity"), "not one of none, strength, all");
  o.calibrate = rd.boolean(rd.require(j, w, "calibrate"), io::child(w, "calibrate"));
  o.elasticity_as = rd.string(rd.require(j, w, "elasticity_as"), io::child(w, "elasticity_as"));
  o.strength = rd.number(rd.require(j, w, "strength"), io::child(w, "strength"), 1e9);
  return o;
}

std::string shard_json(const Plan& plan, const std::vector<std::size_t>& indices, const std::vector<io::Json>& results) {
  std::string out = "{\n\"format\": " + io::Json(kFormat).dump() + ",\n\"experiment\": \"self-contact\",\n\"shard\": " +
                    io::Json::array({plan.opt.shard_index, plan.opt.shard_count}).dump() +
                    ",\n\"tecido\": " + io::provenance_json().dump() + ",\n\"options\": " + options_json(plan.opt).dump() +
                    fmt::format(",\n\"cases\": {},\n\"results\": [", plan.cases.size());
  for (std::size_t k = 0; k < indices.size(); ++k)
    out += (k ? ",\n" : "\n") + io::Json{{"index", indices[k]}, {"result", results[k]}}.dump();
  return out + "\n]\n}\n";
}

bool is_experiment_shard(const io::Json& doc) { return doc.is_object() && doc.contains("format") && doc["format"] == kFormat; }

Merged merge_shards(const std::vector<std::string>& files, const std::string& out_dir, const std::string& seed_table) {
  if (files.empty()) throw io::UsageError("merge: no shard directory given");
  std::vector<ShardFile> shards;
  for (const auto& f : files) shards.push_back(read_shard(f));
  const ShardFile& first = shards.front();
  const int n = first.count;
  shards_by_index(shards);  // the same n, each shard once, none missing
  for (const ShardFile& s : shards)
    if (io::JsonReader(s.file).require(s.doc, "", "options") != first.doc["options"])
      io::JsonReader(s.file).fail("/options", "run with other settings (options) than " + first.file);
  Options o = options_from_json(io::JsonReader(first.file), first.doc["options"], "/options");
  o.out_dir = out_dir;
  if (!seed_table.empty()) o.seed_table_path = seed_table;
  const Plan plan = make_plan(o);
  for (const ShardFile& s : shards) {
    const io::JsonReader rd(s.file);
    if (rd.integer(rd.require(s.doc, "", "cases"), "/cases", 0, std::numeric_limits<std::int64_t>::max()) !=
        static_cast<std::int64_t>(plan.cases.size()))
      rd.fail("/cases", fmt::format("the shards have a different case count than this build's plan ({})", plan.cases.size()));
  }
  Merged m;
  m.shards = n;
  m.cases = plan.cases.size();
  m.outputs = assemble(plan, collect(plan, shards, n));
  return m;
}

}  // namespace tecido::suites::self_contact
