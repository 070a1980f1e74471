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
#include "comparisons/cli/suite_session.h"
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
  SuiteSettings settings;
  std::string shard;
  outside::OutsideOptions outside;
};

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

int run_suite_command(SuiteOptions o) {
  o.settings.sharded = !o.shard.empty();
  const SuiteSession session(o.settings, [&] {
    if (o.settings.sharded && o.outside.any())
      throw io::UsageError("--shard: outside engines (--plugin, --engine-cmd) run unsharded only");
    return load_outside_engines(o.outside);
  });
  const suites::SuiteContext& ctx = session.context();
  if (o.settings.sharded) {
    if (!session.skipped().empty())
      std::cerr << "suite: --shard: skipping " << session.skipped() << " (not split into cases; run them unsharded)\n";
    return run_shard(session.chosen(), ctx, o.shard);
  }
  const int failed = suites::write_report(session.run(std::cerr), ctx);
  std::cout << "report: " << ctx.out_dir << "/report.md (" << failed << " failed checks)\n";
  return failed == 0 ? 0 : 1;
}

Command add_suite(CLI::App& app) {
  auto o = std::make_shared<SuiteOptions>();
  std::string list;
  for (const auto& s : suites::suite_registry()) list += "\n  " + s.name + ": " + s.summary;
  CLI::App* sub = app.add_subcommand("suite", "Run comparison suites and write report.json and report.md. Suites:" + list);
  sub->add_option("names", o->settings.names, "Suite names, or all")->required();
  sub->add_option("--out", o->settings.out, "Output directory")->capture_default_str()->check(non_empty());
  sub->add_flag("--quick", o->settings.quick, "Smaller counts, same checks");
  sub->add_option("--seed", o->settings.seed, "Seed of every random input (written into the report)")
      ->capture_default_str()
      ->check(unsigned_integer());
  sub->add_option("--threads", o->settings.threads, "Worker threads (0 = all cores); results do not depend on it")
      ->check(integer_in(0, io::kMaxThreads));
  sub->add_option("--tolerances", o->settings.tolerances, "Tolerance file (default data/tolerances.json)")->check(non_empty());
  sub->add_option("--data", o->settings.data, "Data directory (default: the source tree's data/)")->check(non_empty());
  std::string sweeps;
  for (const auto& s : suites::suite_registry())
    if (s.sweep) sweeps += (sweeps.empty() ? "" : ", ") + s.name;
  sub->add_option("--shard", o->shard,
                  "Only the cases whose index % n == i of the sweep suites (" + sweeps +
                      "), e.g. 0/8: writes DIR/shard.json; join the shards with `tecido merge`")
      ->check(shard_spec());
  sub->add_option("--engines", o->settings.engines,
                  "Comma-separated engines the suites run (built-in or outside, by name; default: every one). A "
                  "suite runs those it knows; its referee always runs");
  add_outside_options(sub, o->outside);
  return [o]() { return run_suite_command(*o); };
}

}  // namespace

TECIDO_REGISTER_COMMAND(suite, add_suite);

}  // namespace tecido::cli
