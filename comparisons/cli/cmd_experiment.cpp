// tecido experiment self-contact [--out DIR] [--threads N] [--quick] [--runs LIST] [--strength F]
//                                [--scene FILE] [--seed-table FILE] [--elasticity-as stiffness|restitution]
//                                [--shard i/n] [--max-work W]
// The seed's 72-run self-contact experiment (comparisons/suites/experiment_self_contact.h):
// writes DIR/experiment.json and DIR/experiment.md. With --shard i/n only the runs whose index
// % n == i, and only DIR/experiment.json, marked as a shard; `tecido merge` joins the shards.
#include "comparisons/cli/commands.h"
#include "comparisons/cli/option_checks.h"
#include "comparisons/cli/shard_option.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"
#include "comparisons/io/output_dir.h"
#include "comparisons/io/scene_json.h"
#include "comparisons/io/work_limit.h"
#include "comparisons/suites/experiment_self_contact.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>
#include <tuple>
#include <utility>

namespace tecido::cli {

namespace {

/// "0-7,12,20-23" -> indices, each in [0, count): bounds are checked before a range is expanded.
std::vector<int> parse_runs(const std::string& list, int count) {
  std::vector<int> out;
  std::stringstream ss(list);
  std::string item;
  const std::string range = " (run indices are 0.." + std::to_string(count - 1) + ")";
  while (std::getline(ss, item, ',')) {
    if (item.empty()) continue;
    const auto dash = item.find('-', 1);
    const std::string a = item.substr(0, dash), b = dash == std::string::npos ? a : item.substr(dash + 1);
    const auto index = [&](const std::string& t) {
      if (t.empty() || t.find_first_not_of("0123456789") != std::string::npos)
        throw io::UsageError("--runs: \"" + item + "\" is not an index or a range a-b" + range);
      if (t.size() > 9 || std::stoi(t) >= count) throw io::UsageError("--runs: \"" + item + "\" is outside the runs" + range);
      return std::stoi(t);
    };
    const int lo = index(a), hi = index(b);
    if (hi < lo) throw io::UsageError("--runs: \"" + item + "\" is an empty range");
    if (out.size() + static_cast<std::size_t>(hi - lo + 1) > static_cast<std::size_t>(count) * 16)
      throw io::UsageError("--runs: more than " + std::to_string(count * 16) + " run indices");
    for (int i = lo; i <= hi; ++i) out.push_back(i);
  }
  if (out.empty()) throw io::UsageError("--runs: no run index given");
  return out;
}

struct ExperimentOptions {
  std::string name, out = "out/self-contact", runs, scene, seed_table, elasticity_as = "stiffness", shard;
  int threads = 0;
  double strength = 0.0;
  double max_work = io::kDefaultMaxWork;
  bool quick = false;
  CLI::Option* strength_opt = nullptr;
};

/// Every run of the experiment must fit in the work limit: the base scene at the smallest step.
void check_experiment_work(const suites::SelfContactOptions& opt, double max_work) {
  const Scene base = io::load_scene(opt.scene_path);
  double smallest_dt = base.dt;
  for (const auto& run : suites::self_contact_runs()) smallest_dt = std::min(smallest_dt, run.dt);
  const auto steps = static_cast<long long>(std::ceil(opt.simulated_time / smallest_dt));
  const std::string too_much = io::work_limit_problem(base, steps, max_work);
  if (!too_much.empty()) throw io::InputError(opt.scene_path, "", "a run of the experiment: " + too_much);
}

suites::SelfContactOptions experiment_options(const ExperimentOptions& o) {
  if (o.name != "self-contact") throw io::UsageError("unknown experiment \"" + o.name + "\" (known: self-contact)");
  suites::SelfContactOptions opt;
  opt.scene_path = o.scene.empty() ? std::string(TECIDO_SOURCE_DIR) + "/data/scenes/seed_fig21_self_contact.json" : o.scene;
  opt.seed_table_path =
      o.seed_table.empty() ? std::string(TECIDO_SOURCE_DIR) + "/data/seed_tables/self_contact_share.json" : o.seed_table;
  opt.quick = o.quick;
  opt.simulated_time = o.quick ? 2.0 : 10.0;
  opt.threads = o.threads > 0 ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  opt.elasticity_as = o.elasticity_as;
  if (o.strength_opt->count() > 0) opt.strength = o.strength;
  const int count = static_cast<int>(suites::self_contact_runs().size());
  if (!o.runs.empty()) opt.runs = parse_runs(o.runs, count);
  if (!o.shard.empty()) {
    std::tie(opt.shard_index, opt.shard_count) = parse_shard(o.shard);
    std::vector<int> sorted = opt.runs;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw io::UsageError("--shard: --runs must not name a run twice");
  }
  opt.progress = true;
  return opt;
}

int run_experiment(const ExperimentOptions& o) {
  suites::SelfContactOptions opt = experiment_options(o);
  const bool sharded = !o.shard.empty();
  const io::Json seed = io::read_json_file(opt.seed_table_path);
  check_experiment_work(opt, o.max_work);
  io::check_output_dir(o.out);
  const auto t0 = std::chrono::steady_clock::now();
  const auto results = suites::run_self_contact_experiment(opt);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (sharded) {
    io::write_file_atomic(o.out + "/experiment.json", suites::self_contact_shard_json(results, opt));
  } else {
    io::write_file_atomic(o.out + "/experiment.json", suites::self_contact_json(results, opt));
    io::write_file_atomic(o.out + "/experiment.md", suites::self_contact_markdown(results, seed, opt));
  }
  int unstable = 0;
  for (const auto& r : results) unstable += r.status != "ok";
  std::cout << "self-contact: " << results.size() << " runs in " << seconds << " s on " << opt.threads
            << " threads; wrote " << o.out
            << (sharded ? "/experiment.json (shard " + o.shard + ")" : "/experiment.json and experiment.md");
  if (unstable) std::cout << "; " << unstable << " runs went unstable";
  std::cout << "\n";
  return 0;
}

Command add_experiment(CLI::App& app) {
  auto o = std::make_shared<ExperimentOptions>();
  CLI::App* sub = app.add_subcommand("experiment", "Run one of the seed's experiments: self-contact (72 runs, tables 1-3)");
  sub->add_option("name", o->name, "Experiment name: self-contact")->required();
  sub->add_option("--out", o->out, "Output directory (experiment.json, experiment.md)")
      ->capture_default_str()
      ->check(non_empty());
  sub->add_option("--threads", o->threads, "Worker threads (0 = all cores); results do not depend on it")
      ->check(integer_in(0, io::kMaxThreads));
  sub->add_flag("--quick", o->quick, "2 s of simulated time per run instead of 10 (for tests)");
  sub->add_option("--runs", o->runs, "Only these run indices, e.g. 0-7,12 (default: all 72)")->check(non_empty());
  sub->add_option("--scene", o->scene, "Base scene (default data/scenes/seed_fig21_self_contact.json)")->check(non_empty());
  sub->add_option("--seed-table", o->seed_table, "The seed's tables (default data/seed_tables/self_contact_share.json)")
      ->check(non_empty());
  o->strength_opt = sub->add_option("--strength", o->strength,
                                    "Response force per particle [N] (default: the scene's self_collision.strength)")
                        ->check(number_in(0.0, false, 1e9));
  sub->add_option("--elasticity-as", o->elasticity_as, "What the cloth's elasticity is: stiffness | restitution")
      ->capture_default_str()
      ->check(one_of({"stiffness", "restitution"}));
  sub->add_option("--shard", o->shard, "Only the runs whose index % n == i, e.g. 0/8; join the shards with `tecido merge`")
      ->check(shard_spec());
  sub->add_option("--max-work", o->max_work, "Largest work of one run, steps x elements per step (see tecido run)")
      ->capture_default_str()
      ->check(number_in(1.0, false, io::kMaxWorkCeiling));
  return [o]() { return run_experiment(*o); };
}

}  // namespace

TECIDO_REGISTER_COMMAND(experiment, add_experiment);

}  // namespace tecido::cli
