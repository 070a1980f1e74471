// tecido experiment self-contact [--out DIR] [--threads N] [--quick] [--runs LIST] [--strength F]
//                                [--scene FILE] [--seed-table FILE] [--elasticity-as stiffness|restitution]
//                                [--shard i/n]
// The seed's 72-run self-contact experiment (comparisons/suites/experiment_self_contact.h):
// writes DIR/experiment.json and DIR/experiment.md. With --shard i/n only the runs whose index
// % n == i, and only DIR/experiment.json, marked as a shard; `tecido merge` joins the shards.
#include "comparisons/cli/commands.h"
#include "comparisons/cli/shard_option.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/io/input_error.h"
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

/// "0-7,12,20-23" -> indices.
std::vector<int> parse_runs(const std::string& list) {
  std::vector<int> out;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty()) continue;
    const auto dash = item.find('-');
    try {
      std::size_t used = 0;
      if (dash == std::string::npos) {
        out.push_back(std::stoi(item, &used));
        if (used != item.size()) throw std::invalid_argument(item);
      } else {
        const std::string a = item.substr(0, dash), b = item.substr(dash + 1);
        const int lo = std::stoi(a, &used);
        if (used != a.size()) throw std::invalid_argument(item);
        const int hi = std::stoi(b, &used);
        if (used != b.size() || hi < lo) throw std::invalid_argument(item);
        for (int i = lo; i <= hi; ++i) out.push_back(i);
      }
    } catch (const std::exception&) {
      throw io::UsageError("--runs: \"" + item + "\" is not an index or a range a-b");
    }
  }
  if (out.empty()) throw io::UsageError("--runs: no run index given");
  return out;
}

Command add_experiment(CLI::App& app) {
  struct Opts {
    std::string name, out = "out/self-contact", runs, scene, seed_table, elasticity_as = "stiffness", shard;
    int threads = 0;
    double strength = std::nan("");  // not given
    bool quick = false;
  };
  auto o = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand("experiment", "Run one of the seed's experiments: self-contact (72 runs, tables 1-3)");
  sub->add_option("name", o->name, "Experiment name: self-contact")->required();
  sub->add_option("--out", o->out, "Output directory (experiment.json, experiment.md)")->capture_default_str();
  sub->add_option("--threads", o->threads, "Worker threads (0 = all cores); results do not depend on it");
  sub->add_flag("--quick", o->quick, "2 s of simulated time per run instead of 10 (for tests)");
  sub->add_option("--runs", o->runs, "Only these run indices, e.g. 0-7,12 (default: all 72)");
  sub->add_option("--scene", o->scene, "Base scene (default data/scenes/seed_fig21_self_contact.json)");
  sub->add_option("--seed-table", o->seed_table, "The seed's tables (default data/seed_tables/self_contact_share.json)");
  sub->add_option("--strength", o->strength, "Response force per particle [N] (default: the scene's self_collision.strength)");
  sub->add_option("--elasticity-as", o->elasticity_as, "What the cloth's elasticity is: stiffness | restitution")
      ->capture_default_str();
  sub->add_option("--shard", o->shard, "Only the runs whose index % n == i, e.g. 0/8; join the shards with `tecido merge`");
  return [o]() {
    if (o->name != "self-contact") throw io::UsageError("unknown experiment \"" + o->name + "\" (known: self-contact)");
    if (o->elasticity_as != "stiffness" && o->elasticity_as != "restitution")
      throw io::UsageError("--elasticity-as must be stiffness or restitution");
    if (o->threads < 0) throw io::UsageError("--threads must be >= 0");
    suites::SelfContactOptions opt;
    opt.scene_path = o->scene.empty() ? std::string(TECIDO_SOURCE_DIR) + "/data/scenes/seed_fig21_self_contact.json" : o->scene;
    opt.seed_table_path =
        o->seed_table.empty() ? std::string(TECIDO_SOURCE_DIR) + "/data/seed_tables/self_contact_share.json" : o->seed_table;
    opt.quick = o->quick;
    opt.simulated_time = o->quick ? 2.0 : 10.0;
    opt.threads = o->threads > 0 ? o->threads : std::max(1u, std::thread::hardware_concurrency());
    opt.elasticity_as = o->elasticity_as;
    if (!std::isnan(o->strength)) {
      if (!(o->strength >= 0.0) || !(o->strength <= 1e9)) throw io::UsageError("--strength must be in [0, 1e9]");
      opt.strength = o->strength;
    }
    if (!o->runs.empty()) opt.runs = parse_runs(o->runs);
    const bool sharded = !o->shard.empty();
    if (sharded) {
      std::tie(opt.shard_index, opt.shard_count) = parse_shard(o->shard);
      std::vector<int> sorted = opt.runs;
      std::sort(sorted.begin(), sorted.end());
      if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
        throw io::UsageError("--shard: --runs must not name a run twice");
    }
    opt.progress = true;
    const io::Json seed = io::read_json_file(opt.seed_table_path);
    const auto t0 = std::chrono::steady_clock::now();
    const auto results = suites::run_self_contact_experiment(opt);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (sharded) {
      io::write_file_atomic(o->out + "/experiment.json", suites::self_contact_shard_json(results, opt));
    } else {
      io::write_file_atomic(o->out + "/experiment.json", suites::self_contact_json(results, opt));
      io::write_file_atomic(o->out + "/experiment.md", suites::self_contact_markdown(results, seed, opt));
    }
    int unstable = 0;
    for (const auto& r : results) unstable += r.status != "ok";
    std::cout << "self-contact: " << results.size() << " runs in " << seconds << " s on " << opt.threads
              << " threads; wrote " << o->out << (sharded ? "/experiment.json (shard " + o->shard + ")" : "/experiment.json and experiment.md");
    if (unstable) std::cout << "; " << unstable << " runs went unstable";
    std::cout << "\n";
    return 0;
  };
}

}  // namespace

TECIDO_REGISTER_COMMAND(experiment, add_experiment);

}  // namespace tecido::cli
