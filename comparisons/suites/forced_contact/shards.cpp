#include "comparisons/suites/forced_contact/shards.h"

#include "comparisons/io/limits.h"

namespace tecido::suites::forced_contact {

io::Json options_json(const Options& o) { return {{"quick", o.quick}, {"seeds", o.seeds}}; }

std::string shard_json(const Plan& plan, const std::vector<std::size_t>& indices, const std::vector<io::Json>& results) {
  return experiment_shard_json("forced-contact", plan.opt.shard_index, plan.opt.shard_count, options_json(plan.opt),
                               plan.cases.size(), indices, results);
}

Merged merge_shards(const std::vector<std::string>& files, const std::string& out_dir) {
  const std::vector<ShardFile> shards = read_experiment_shards(files, "forced-contact");
  const ShardFile& first = shards.front();
  const io::JsonReader rd(first.file);
  const io::Json& j = first.doc["options"];
  rd.require_object(j, "/options");
  Options o;
  o.quick = rd.boolean(rd.require(j, "/options", "quick"), "/options/quick");
  o.seeds = static_cast<int>(rd.integer(rd.require(j, "/options", "seeds"), "/options/seeds", 0, io::kMaxSeeds));
  o.out_dir = out_dir;
  const Plan plan = make_plan(o);
  Merged m;
  m.shards = first.count;
  m.cases = plan.cases.size();
  m.outputs = assemble(plan, collect_experiment_results(shards, plan.cases.size(),
                                                        [&plan](std::size_t k) { return case_id(plan.cases[k]); }));
  return m;
}

}  // namespace tecido::suites::forced_contact
