// tecido experiment self-contact [--out DIR] [--threads N] [--quick] [--seeds N]
//                                [--detector core|core-mt|core-rotation[,...]] [--runs LIST]
//                                [--calibrate] [--calibration FILE] [--sensitivity none|strength|all]
//                                [--no-sensitivity]
//                                [--scene FILE] [--seed-table FILE]
//                                [--elasticity-as stiffness|restitution] [--strength F] [--shard i/n]
//                                [--max-work W]
// tecido experiment self-contact --runs LIST --view [--out DIR] [--quick] [other self-contact options]
// The seed's self-contact experiment as an ensemble, its claims judged by stated rules
// (comparisons/suites/self_contact/experiment.h): writes DIR/experiment.json and experiment.md
// (with --calibrate: DIR/calibration.json and calibration.md). With --shard i/n only the cases whose
// index % n == i, written as DIR/experiment.json (or calibration.json) marked as a shard;
// `tecido merge` joins the shards. With --view, instead of the ensemble: the first run (wind seed 0,
// the baseline reading) of each cell of --runs as a page, DIR/runs/<cell>/index.html (as `tecido run
// --out` writes), a frame every 0.02 s.
//
// tecido experiment forced-contact [--out DIR] [--threads N] [--quick] [--seeds N] [--shard i/n]
//                                  [--max-work W] [--frames]
// The seed's argument for GIA (fig. 16) as an experiment (comparisons/suites/forced_contact/
// experiment.h): the same outputs, shards and merge; --frames also writes run 0 of every
// (response, hold) as OBJ frames under DIR/frames/. The self-contact options are refused.
#include "comparisons/io/source_dir.h"
#include "comparisons/cli/commands.h"
#include "comparisons/cli/option_checks.h"
#include "comparisons/cli/shard_option.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"
#include "comparisons/io/output_dir.h"
#include "comparisons/io/scene_json.h"
#include "comparisons/io/work_limit.h"
#include "comparisons/suites/forced_contact/frames.h"
#include "comparisons/suites/forced_contact/shards.h"
#include "comparisons/suites/self_contact/experiment.h"
#include "comparisons/suites/self_contact/shards.h"
#include "comparisons/suites/suite_shard.h"
#include "comparisons/view/run_recording.h"
#include "comparisons/view/view_page.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>
#include <tuple>

namespace tecido::cli {

namespace {

namespace sc = suites::self_contact;
namespace fc = suites::forced_contact;

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

struct Opts {
  std::string name, out, runs, scene, seed_table, calibration, elasticity_as, shard, detector;
  std::string sensitivity = "strength";
  int threads = 0, seeds = 0;
  double max_work = io::kDefaultMaxWork;
  double strength = std::nan("");  // not given
  bool quick = false, calibrate = false, no_sensitivity = false, frames = false, view = false;
};

/// The subcommand's options, all in one place.
void define_options(CLI::App* sub, Opts& o) {
  sub->add_option("name", o.name, "Experiment name: self-contact | forced-contact")->required();
  sub->add_option("--out", o.out, "Output directory (experiment.json and .md; calibration.json and .md); default out/NAME")
      ->check(non_empty());
  sub->add_option("--threads", o.threads, "Worker threads (0 = all cores); results do not depend on it")
      ->check(integer_in(0, io::kMaxThreads));
  sub->add_flag("--quick", o.quick, "2 s per run, 2 seeds, core-mt only, no sensitivity (for CI)");
  sub->add_option("--seeds", o.seeds, "Runs per cell with independent wind seeds (default 10; 2 with --quick)")
      ->check(integer_in(1, io::kMaxSeeds));
  sub->add_option("--detector", o.detector,
                  "What counts as a self-contact frame: core, core-mt, core-rotation, or a list (default core-mt,core)")
      ->check(non_empty());
  sub->add_option("--runs", o.runs, "Only these cells, e.g. 0-7,12 (default: all 72; timing claims need all)")
      ->check(non_empty());
  sub->add_flag("--calibrate", o.calibrate, "Fit air drag and swirl rate on the calibration cells; writes calibration.json");
  sub->add_option("--calibration", o.calibration,
                  "Calibration record (default data/seed_tables/self_contact_calibration.json)")
      ->check(non_empty());
  sub->add_option("--sensitivity", o.sensitivity,
                  "Readings beside the baseline: none, strength (the push strengths tried, 0.4x and 2x) or all "
                  "(every open choice, 11 readings: long)")
      ->capture_default_str()
      ->check(one_of({"none", "strength", "all"}));
  sub->add_flag("--no-sensitivity", o.no_sensitivity, "The same as --sensitivity none");
  sub->add_option("--scene", o.scene, "Base scene (default data/scenes/seed_fig21_self_contact.json)")->check(non_empty());
  sub->add_option("--seed-table", o.seed_table, "The seed's tables (default data/seed_tables/self_contact_share.json)")
      ->check(non_empty());
  sub->add_option("--strength", o.strength, "Edge modes' push per particle [N] (default: the scene's)")
      ->check(number_in(0.0, false, 1e9));
  sub->add_option("--elasticity-as", o.elasticity_as, "What the cloth's elasticity is: stiffness (default) | restitution")
      ->check(one_of({"stiffness", "restitution"}));
  sub->add_option("--shard", o.shard, "Only the cases whose index % n == i, e.g. 0/8; join the shards with `tecido merge`")
      ->check(shard_spec());
  sub->add_flag("--frames", o.frames, "forced-contact: also write run 0 of every (response, hold) as OBJ frames in DIR/frames");
  sub->add_flag("--view", o.view,
                "self-contact: instead of the ensemble, write the first run (wind seed 0) of each --runs cell as a "
                "3-D page, DIR/runs/<cell>/index.html");
  sub->add_option("--max-work", o.max_work, "Largest work of one run, steps x elements per step (see tecido run)")
      ->capture_default_str()
      ->check(number_in(1.0, false, io::kMaxWorkCeiling));
}

/// Every run of the experiment must fit in the work limit: the base scene at the smallest step.
void check_experiment_work(const sc::Options& opt, double max_work) {
  const Scene base = io::load_scene(opt.scene_path);
  double smallest_dt = base.dt;
  for (const double dt : sc::CellGrid::steps) smallest_dt = std::min(smallest_dt, dt);
  const auto steps = static_cast<long long>(std::ceil(sc::settings(opt.quick).simulated_time / smallest_dt));
  const std::string too_much = io::work_limit_problem(base, steps, max_work);
  if (!too_much.empty()) throw io::InputError(opt.scene_path, "", "a run of the experiment: " + too_much);
}

int threads_of(const Opts& o) {
  return o.threads > 0 ? o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

sc::Options to_options(const Opts& o) {
  if (o.frames) throw io::UsageError("--frames is an option of forced-contact, not self-contact");
  const std::string data = std::string(TECIDO_SOURCE_DIR) + "/data";
  sc::Options opt;
  opt.scene_path = o.scene.empty() ? data + "/scenes/seed_fig21_self_contact.json" : o.scene;
  opt.seed_table_path = o.seed_table.empty() ? data + "/seed_tables/self_contact_share.json" : o.seed_table;
  opt.calibration_path = o.calibration.empty() ? data + "/seed_tables/self_contact_calibration.json" : o.calibration;
  opt.quick = o.quick;
  opt.seeds = o.seeds;
  if (!o.detector.empty())
    opt.detectors = parse_engine_list(o.detector, {"core", "core-mt", "core-rotation"}, "self-contact", "--detector");
  if (!o.runs.empty()) opt.cells = parse_runs(o.runs, sc::CellGrid::kCells);
  opt.calibrate = o.calibrate;
  opt.sensitivity = o.no_sensitivity ? "none" : o.sensitivity;
  opt.elasticity_as = o.elasticity_as;
  if (!std::isnan(o.strength)) opt.strength = o.strength;
  opt.threads = threads_of(o);
  if (!o.shard.empty()) std::tie(opt.shard_index, opt.shard_count) = parse_shard(o.shard);
  opt.progress = true;
  opt.out_dir = o.out;
  return opt;
}

/// forced-contact: the self-contact-only options are refused (exit 2), the shared ones read.
fc::Options forced_options(const Opts& o, CLI::App* sub) {
  for (const char* name : {"--detector", "--runs", "--calibrate", "--calibration", "--no-sensitivity", "--sensitivity",
                           "--scene",
                           "--seed-table", "--strength", "--elasticity-as"})
    if (sub->count(name) > 0) throw io::UsageError(std::string(name) + " is an option of self-contact, not forced-contact");
  fc::Options opt;
  opt.quick = o.quick;
  opt.seeds = o.seeds;
  opt.threads = threads_of(o);
  if (!o.shard.empty()) std::tie(opt.shard_index, opt.shard_count) = parse_shard(o.shard);
  opt.progress = true;
  opt.out_dir = o.out;
  return opt;
}

/// Every run of forced-contact must fit in the work limit: the longest hold.
void check_forced_work(const fc::Plan& plan, double max_work) {
  const fc::Settings& s = plan.settings;
  const Scene longest = fc::forced_scene(plan.scene, SelfCollisionResponse::None, s.holds.back(), s.after_release, 0);
  const std::string too_much = io::work_limit_problem(longest, longest.steps, max_work);
  if (!too_much.empty()) throw io::UsageError("--max-work: a run of forced-contact: " + too_much);
}

int run_forced(const Opts& o, CLI::App* sub) {
  const fc::Options opt = forced_options(o, sub);
  const auto plan = std::make_shared<const fc::Plan>(fc::make_plan(opt));
  check_forced_work(*plan, o.max_work);
  io::check_output_dir(o.out);
  const io::OutputDirLock out_lock(o.out);
  const suites::Sweep sweep = fc::make_sweep(plan);
  const auto indices = suites::shard_indices(sweep.cases, opt.shard_index, opt.shard_count);
  const auto t0 = std::chrono::steady_clock::now();
  const auto results = suites::run_sweep_cases(sweep, indices, opt.threads, "forced-contact", opt.progress);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "forced-contact: " << indices.size() << " cases in " << seconds << " s on " << opt.threads << " threads; ";
  if (!o.shard.empty()) {
    io::write_file_atomic(o.out + "/experiment.json", fc::shard_json(*plan, indices, results));
    std::cout << "wrote " << o.out << "/experiment.json (shard " << o.shard << ")\n";
  } else {
    const fc::Outputs out = fc::assemble(*plan, results);
    for (const auto& [name, text] : out.files) io::write_file_atomic(o.out + "/" + name, text);
    std::cout << out.summary << "; wrote " << o.out << "/experiment.json and .md\n";
  }
  if (o.frames) std::cout << "forced-contact: " << fc::write_frames(*plan, o.out) << " frames in " << o.out << "/frames\n";
  return 0;
}

/// Seconds between the frames of a --view page.
constexpr double kViewFrameInterval = 0.02;

/// self-contact --view: the first run of each --runs cell (wind seed 0, the baseline reading: the
/// very run the ensemble makes) as DIR/runs/<cell>/index.html.
int write_run_views(const sc::Plan& plan, const std::string& out) {
  for (int cell : plan.cells) {
    const Scene scene = sc::run_case_scene(plan, {sc::CaseSpec::Run, 0, cell, 0, 0});
    const long long every = std::max(1LL, std::llround(kViewFrameInterval / scene.dt));
    const std::string title = "tecido experiment self-contact, run " + std::to_string(cell) + " (" +
                              sc::mode_label(sc::CellGrid::cell(cell).mode) + "), wind seed 0";
    const std::string dir = out + "/runs/" + std::to_string(cell);
    view::write_view_page(dir, "index", title, view::record_run_page(scene, every, title));
    std::cout << "page " << dir << "/index.html\n";
  }
  return 0;
}

int run(Opts o, CLI::App* sub) {
  if (o.name != "self-contact" && o.name != "forced-contact")
    throw io::UsageError("unknown experiment \"" + o.name + "\" (known: self-contact, forced-contact)");
  if (o.out.empty()) o.out = "out/" + o.name;
  if (o.view && o.name != "self-contact") throw io::UsageError("--view is an option of self-contact, not forced-contact");
  if (o.name == "forced-contact") return run_forced(o, sub);
  if (o.view && (o.runs.empty() || o.calibrate || !o.shard.empty()))
    throw io::UsageError("--view needs --runs (the cells to draw) and goes with neither --calibrate nor --shard");
  const sc::Options opt = to_options(o);
  check_experiment_work(opt, o.max_work);
  io::check_output_dir(o.out);
  const io::OutputDirLock out_lock(o.out);  // a second run into this --out refuses
  const auto plan = std::make_shared<const sc::Plan>(sc::make_plan(opt));
  if (o.view) return write_run_views(*plan, o.out);
  const suites::Sweep sweep = sc::make_sweep(plan);
  const auto indices = suites::shard_indices(sweep.cases, opt.shard_index, opt.shard_count);
  const auto t0 = std::chrono::steady_clock::now();
  const auto results = suites::run_sweep_cases(sweep, indices, opt.threads, "self-contact", opt.progress);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string file = opt.calibrate ? "calibration.json" : "experiment.json";
  std::cout << "self-contact: " << indices.size() << " cases in " << seconds << " s on " << opt.threads << " threads; ";
  if (opt.shard_count > 1 || !o.shard.empty()) {
    io::write_file_atomic(o.out + "/" + file, sc::shard_json(*plan, indices, results));
    std::cout << "wrote " << o.out << "/" << file << " (shard " << o.shard << ")\n";
    return 0;
  }
  const sc::Outputs out = sc::assemble(*plan, results);
  for (const auto& [name, text] : out.files) io::write_file_atomic(o.out + "/" + name, text);
  std::cout << out.summary << "; wrote " << o.out << "/" << file << " and .md\n";
  return 0;
}

Command add_experiment(CLI::App& app) {
  auto o = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand(
      "experiment", "Run one of the seed's experiments: self-contact (tables 1-3, as an ensemble) or forced-contact (fig. 16)");
  define_options(sub, *o);
  return [o, sub]() { return run(*o, sub); };
}

}  // namespace

TECIDO_REGISTER_COMMAND(experiment, add_experiment);

}  // namespace tecido::cli
