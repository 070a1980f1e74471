// tecido suite NAME... | all [--out DIR] [--quick] [--seed N] [--threads N] [--tolerances FILE] [--shard i/n]
// Runs the suites and writes DIR/report.json and DIR/report.md. The sweep suites (tritri, stability,
// tradeoff) run their cases on --threads threads with a progress bar on a terminal. With --shard i/n
// only their cases whose index % n == i run, and DIR/shard.json holds the case results instead of a
// report (comparisons/suites/suite_shard.h); `tecido merge` assembles the report from the shards.
// `all --shard` shards the sweep suites and skips the others (saying so on stderr); naming a suite
// that cannot be sharded is a usage error.
#include "comparisons/cli/commands.h"
#include "comparisons/cli/outside_options.h"
#include "comparisons/cli/option_checks.h"
#include "comparisons/cli/shard_option.h"
#include "comparisons/engines/run_engines.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/io/gnuplot.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"
#include "comparisons/io/output_dir.h"
#include "comparisons/suites/report.h"
#include "comparisons/suites/suite_shard.h"
#include "comparisons/suites/sweep.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <thread>
#include <tuple>
#include <unistd.h>

namespace tecido::cli {

namespace {

struct SuiteOptions {
  std::vector<std::string> names;
  std::string out = "out";
  std::string tolerances;
  std::string data;
  std::string shard;
  bool quick = false;
  std::uint64_t seed = 20141;
  int threads = 0;
  std::string engines;
  outside::OutsideOptions outside;
};

/// The suites named (`all` = every one; with --shard, every sweep, the others listed in `skipped`).
std::vector<const suites::SuiteEntry*> chosen_suites(const std::vector<std::string>& names, bool sharded,
                                                     std::string& skipped) {
  const auto& reg = suites::suite_registry();
  std::vector<const suites::SuiteEntry*> chosen;
  for (const auto& name : names) {
    if (name == "all") {
      for (const auto& s : reg) {
        if (sharded && !s.sweep) skipped += (skipped.empty() ? "" : ", ") + s.name;
        else chosen.push_back(&s);
      }
      continue;
    }
    auto it = std::find_if(reg.begin(), reg.end(), [&](const suites::SuiteEntry& e) { return e.name == name; });
    if (it == reg.end()) {
      std::string all;
      for (const auto& s : reg) all += (all.empty() ? "" : ", ") + s.name;
      throw io::UsageError("unknown suite \"" + name + "\" (known: " + all + ", all)");
    }
    if (sharded && !it->sweep) {
      std::string can;
      for (const auto& s : reg)
        if (s.sweep) can += (can.empty() ? "" : ", ") + s.name;
      throw io::UsageError("--shard: suite \"" + name + "\" cannot be sharded (only " + can + " can)");
    }
    chosen.push_back(&*it);
  }
  return chosen;
}

/// --shard i/n: the chosen sweeps' cases of this shard, into DIR/shard.json.
int run_shard(const std::vector<const suites::SuiteEntry*>& chosen, const suites::SuiteContext& ctx,
              const std::string& shard) {
  const auto [shard_index, shard_count] = parse_shard(shard);
  std::vector<suites::SuiteSlice> slices;
  std::string summary;
  for (const auto* s : chosen) {
    const auto t0 = std::chrono::steady_clock::now();
    const suites::Sweep sweep = s->sweep(ctx);
    suites::SuiteSlice sl;
    sl.name = s->name;
    sl.cases = sweep.cases;
    sl.indices = suites::shard_indices(sweep.cases, shard_index, shard_count);
    sl.results = suites::run_sweep_cases(sweep, sl.indices, ctx.threads, "suite " + s->name + " " + shard, ctx.progress);
    sl.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    summary += (summary.empty() ? "" : ", ") + s->name + " " + std::to_string(sl.indices.size()) + " of " +
               std::to_string(sl.cases) + " cases";
    slices.push_back(std::move(sl));
  }
  io::write_file_atomic(ctx.out_dir + "/shard.json", suites::suite_shard_json(slices, ctx, shard_index, shard_count));
  std::cout << "suite shard " << shard << ": " << summary << "; wrote " << ctx.out_dir << "/shard.json\n";
  return 0;
}

/// The chosen suites in order, a progress line each on stderr, then the report.
int run_suites(const std::vector<const suites::SuiteEntry*>& chosen, const suites::SuiteContext& ctx) {
  io::create_output_directories(ctx.out_dir);
  std::vector<suites::SuiteResult> results;
  for (const auto* s : chosen) {
    std::cerr << "suite " << s->name << " ..." << std::flush;
    suites::SuiteResult r;
    try {
      r = suites::run_suite(*s, ctx);
    } catch (...) {
      std::cerr << "\n";  // end the progress line: the error gets a line of its own
      throw;
    }
    int failed = 0;
    for (const auto& c : r.checks) failed += c.pass ? 0 : 1;
    // On a terminal a sweep's progress bar took the line: name the suite again.
    if (s->sweep && ::isatty(2) == 1) std::cerr << "suite " << s->name << ":";
    std::cerr << " " << r.checks.size() - failed << " passed, " << failed << " failed (" << r.seconds << " s)\n";
    for (const std::string& line : r.stderr_lines) std::cerr << "  " << line << "\n";
    results.push_back(std::move(r));
  }
  const int failed = suites::write_report(results, ctx);
  std::cout << "report: " << ctx.out_dir << "/report.md (" << failed << " failed checks)\n";
  return failed == 0 ? 0 : 1;
}

int run_suite_command(const SuiteOptions& o) {
  const bool sharded = !o.shard.empty();
  std::string skipped;
  const auto chosen = chosen_suites(o.names, sharded, skipped);
  suites::SuiteContext ctx;
  ctx.data_dir = o.data.empty() ? std::string(TECIDO_SOURCE_DIR) + "/data" : o.data;
  const suites::Tolerances tol = suites::Tolerances::load(o.tolerances.empty() ? ctx.data_dir + "/tolerances.json" : o.tolerances);
  ctx.out_dir = o.out;
  ctx.quick = o.quick;
  ctx.seed = o.seed;
  ctx.threads = o.threads > 0 ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  ctx.tolerances = &tol;
  ctx.gnuplot = io::gnuplot_available();
  ctx.progress = true;
  io::check_output_dir(ctx.out_dir);
  const io::OutputDirLock out_lock(ctx.out_dir);  // a second run into this --out refuses
  if (sharded && o.outside.any())
    throw io::UsageError("--shard: outside engines (--plugin, --engine-cmd) run unsharded only");
  const auto outside = load_outside_engines(o.outside);
  ctx.outside = outside;
  if (!o.engines.empty()) {
    std::vector<std::string> known = builtin_engine_names();
    for (const auto& e : outside->all()) known.push_back(e->name());
    ctx.engines = parse_engine_list(o.engines, known, "suite");
  }
  if (!sharded) return run_suites(chosen, ctx);
  if (!skipped.empty()) std::cerr << "suite: --shard: skipping " << skipped << " (not split into cases; run them unsharded)\n";
  return run_shard(chosen, ctx, o.shard);
}

Command add_suite(CLI::App& app) {
  auto o = std::make_shared<SuiteOptions>();
  std::string list;
  for (const auto& s : suites::suite_registry()) list += "\n  " + s.name + ": " + s.summary;
  CLI::App* sub = app.add_subcommand("suite", "Run comparison suites and write report.json and report.md. Suites:" + list);
  sub->add_option("names", o->names, "Suite names, or all")->required();
  sub->add_option("--out", o->out, "Output directory")->capture_default_str()->check(non_empty());
  sub->add_flag("--quick", o->quick, "Smaller counts, same checks");
  sub->add_option("--seed", o->seed, "Seed of every random input (written into the report)")
      ->capture_default_str()
      ->check(unsigned_integer());
  sub->add_option("--threads", o->threads, "Worker threads (0 = all cores); results do not depend on it")
      ->check(integer_in(0, io::kMaxThreads));
  sub->add_option("--tolerances", o->tolerances, "Tolerance file (default data/tolerances.json)")->check(non_empty());
  sub->add_option("--data", o->data, "Data directory (default: the source tree's data/)")->check(non_empty());
  std::string sweeps;
  for (const auto& s : suites::suite_registry())
    if (s.sweep) sweeps += (sweeps.empty() ? "" : ", ") + s.name;
  sub->add_option("--shard", o->shard,
                  "Only the cases whose index % n == i of the sweep suites (" + sweeps +
                      "), e.g. 0/8: writes DIR/shard.json; join the shards with `tecido merge`")
      ->check(shard_spec());
  sub->add_option("--engines", o->engines,
                  "Comma-separated engines the suites run (built-in or outside, by name; default: every one). A "
                  "suite runs those it knows; its referee always runs");
  add_outside_options(sub, o->outside);
  return [o]() { return run_suite_command(*o); };
}

}  // namespace

TECIDO_REGISTER_COMMAND(suite, add_suite);

}  // namespace tecido::cli
