// tecido merge DIR... --out DIR2 [--seed-table FILE]
//  (DIR/experiment.json of `tecido experiment forced-contact --shard i/n`: the same, its experiment
//  named in the shard, comparisons/suites/forced_contact/shards.h)
// Joins shards into the result of the unsharded run. Each DIR holds one shard (or is its file):
//  - DIR/experiment.json of `tecido experiment self-contact --shard i/n`: writes DIR2/experiment.json
//    and DIR2/experiment.md, byte for byte what the unsharded run writes (comparisons/suites/self_contact/shards.h);
//  - DIR/shard.json of `tecido suite NAME... --shard i/n`: assembles each suite from its cases and
//    writes DIR2/report.json, DIR2/report.md and plots, what the unsharded run writes but for
//    wall-clock measurements (comparisons/suites/suite_shard.h); exit 1 when a check fails.
// Inconsistent shards (a different n, a shard given twice or missing, a case twice or missing,
// other settings, the two kinds mixed): one line, exit 2, nothing written.
#include "comparisons/cli/commands.h"
#include "comparisons/cli/option_checks.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/io/output_dir.h"
#include "comparisons/io/gnuplot.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/report.h"
#include "comparisons/suites/forced_contact/shards.h"
#include "comparisons/suites/self_contact/shards.h"
#include "comparisons/suites/suite_shard.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

namespace tecido::cli {

namespace {

/// DIR -> the shard file in it: shard.json (a suite shard) when present, else experiment.json, else
/// calibration.json (an experiment's calibration shard).
std::string shard_file(const std::string& d) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(d, ec)) return d;
  for (const char* name : {"shard.json", "experiment.json", "calibration.json"}) {
    const auto f = std::filesystem::path(d) / name;
    if (std::filesystem::is_regular_file(f, ec)) return f.string();
  }
  return (std::filesystem::path(d) / "experiment.json").string();
}

template <class Merged>
int write_merged(const Merged& m, const std::string& out) {
  for (const auto& [name, text] : m.outputs.files) io::write_file_atomic(out + "/" + name, text);
  std::cout << "merge: " << m.shards << " shards, " << m.cases << " cases; " << m.outputs.summary << "; wrote " << out
            << "/" << m.outputs.files.front().first << " and .md\n";
  return 0;
}

/// The experiment the first shard names decides the merge (the others must be of the same one).
int merge_experiment(const std::vector<std::string>& files, const std::string& out, const std::string& seed_table) {
  std::error_code ec;
  const bool forced = std::filesystem::is_regular_file(files.front(), ec) &&
                      suites::shard_experiment(io::read_json_file(files.front())) == "forced-contact";
  if (forced) {
    if (!seed_table.empty()) throw io::UsageError("--seed-table is for self-contact shards, not forced-contact");
    return write_merged(suites::forced_contact::merge_shards(files, out), out);
  }
  return write_merged(suites::self_contact::merge_shards(files, out, seed_table), out);
}

int merge_suites(const std::vector<std::string>& files, const std::string& out) {
  const suites::MergedSuites m = suites::merge_suite_shards(files);
  suites::SuiteContext ctx;
  ctx.out_dir = out;
  ctx.data_dir = m.data_dir;
  ctx.quick = m.quick;
  ctx.seed = m.seed;
  ctx.threads = 1;
  ctx.tolerances = &m.tolerances;
  ctx.gnuplot = io::gnuplot_available();
  // Every suite's sweep first: a case count that does not match this build is bad input.
  std::vector<suites::Sweep> sweeps;
  const auto& reg = suites::suite_registry();
  for (std::size_t s = 0; s < m.suites.size(); ++s) {
    const auto& sl = m.suites[s];
    const auto it = std::find_if(reg.begin(), reg.end(), [&](const suites::SuiteEntry& e) { return e.name == sl.name; });
    sweeps.push_back(it->sweep(ctx));
    if (sweeps.back().cases != sl.cases)
      throw io::InputError(files.front(), io::child(io::child("/suites", s), "cases"),
                           sl.name + " has " + std::to_string(sl.cases) + " cases here but " +
                               std::to_string(sweeps.back().cases) + " in this build (another build or engine list)");
  }
  std::vector<suites::SuiteResult> results;
  for (std::size_t s = 0; s < m.suites.size(); ++s) {
    const auto& sl = m.suites[s];
    suites::SuiteResult r;
    try {
      r = sweeps[s].assemble(sl.results);
    } catch (const io::InputError&) {
      throw;
    } catch (const std::exception& e) {
      throw io::InputError(files.front(), io::child(io::child("/suites", s), "results"),
                           sl.name + ": case results this build cannot read (" + e.what() + ")");
    }
    r.name = sl.name;
    r.seconds = sl.seconds;
    for (const std::string& line : r.stderr_lines) std::cerr << line << "\n";  // as `tecido suite` prints them
    results.push_back(std::move(r));
  }
  const int failed = suites::write_report(results, ctx);
  std::cout << "merge: " << m.shards << " shards, " << m.suites.size() << " suites; report: " << out << "/report.md ("
            << failed << " failed checks)\n";
  return failed == 0 ? 0 : 1;
}

Command add_merge(CLI::App& app) {
  struct Opts {
    std::vector<std::string> dirs;
    std::string out, seed_table;
  };
  auto o = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand(
      "merge", "Join the shards of `experiment self-contact|forced-contact --shard i/n` or `suite NAME... --shard i/n` into one result");
  sub->add_option("dirs", o->dirs, "The shards' output directories (or their experiment.json / shard.json files)")
      ->required()
      ->check(non_empty());
  sub->add_option("--out", o->out, "Output directory (experiment.json and .md, or report.json, report.md and plots)")
      ->required()
      ->check(non_empty());
  sub->add_option("--seed-table", o->seed_table,
                  "Experiment shards: the seed's tables (default: the path recorded in the shards)")
      ->check(non_empty());
  return [o]() {
    std::vector<std::string> files;
    for (const auto& d : o->dirs) files.push_back(shard_file(d));
    // One kind at a time: the first file decides, the others must agree.
    bool suite_kind = false;
    for (std::size_t k = 0; k < files.size(); ++k) {
      std::error_code ec;
      if (!std::filesystem::is_regular_file(files[k], ec)) break;  // the merge reports the missing file
      const bool is_suite = suites::is_suite_shard(io::read_json_file(files[k]));
      if (k == 0) suite_kind = is_suite;
      if (is_suite != suite_kind)
        throw io::InputError(files[k], "", std::string("a ") + (is_suite ? "suite" : "experiment") + " shard, but " +
                                               files[0] + " is " + (suite_kind ? "a suite" : "an experiment") +
                                               " shard: merge one kind at a time");
    }
    if (suite_kind && !o->seed_table.empty()) throw io::UsageError("--seed-table: applies to experiment shards only");
    io::check_output_dir(o->out);
    const io::OutputDirLock out_lock(o->out);  // a second run into this --out refuses
    if (suite_kind) {
      return merge_suites(files, o->out);
    }
    return merge_experiment(files, o->out, o->seed_table);
  };
}

}  // namespace

TECIDO_REGISTER_COMMAND(merge, add_merge);

}  // namespace tecido::cli
