#include "comparisons/suites/self_contact/shards.h"

#include "comparisons/io/input_error.h"
#include "comparisons/suites/experiment_shard.h"

#include <fmt/format.h>


namespace tecido::suites::self_contact {

namespace {

std::vector<std::string> strings(const io::JsonReader& rd, const io::Json& j, const std::string& where) {
  std::vector<std::string> out;
  const io::Json& a = rd.require_array(j, where);
  for (std::size_t k = 0; k < a.size(); ++k) out.push_back(rd.string(a[k], io::child(where, k)));
  return out;
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
  return experiment_shard_json("self-contact", plan.opt.shard_index, plan.opt.shard_count, options_json(plan.opt),
                               plan.cases.size(), indices, results);
}

Merged merge_shards(const std::vector<std::string>& files, const std::string& out_dir, const std::string& seed_table) {
  const std::vector<ShardFile> shards = read_experiment_shards(files, "self-contact");
  const ShardFile& first = shards.front();
  Options o = options_from_json(io::JsonReader(first.file), first.doc["options"], "/options");
  o.out_dir = out_dir;
  if (!seed_table.empty()) o.seed_table_path = seed_table;
  const Plan plan = make_plan(o);
  const auto case_id = [&plan](std::size_t k) {
    const CaseSpec& c = plan.cases[k];
    return io::Json{static_cast<int>(c.kind), c.variant, c.cell, c.seed, c.grid};
  };
  Merged m;
  m.shards = first.count;
  m.cases = plan.cases.size();
  m.outputs = assemble(plan, collect_experiment_results(shards, plan.cases.size(), case_id));
  return m;
}

}  // namespace tecido::suites::self_contact
