// tecido merge DIR... --out DIR2 [--seed-table FILE]
// Joins the shards of `tecido experiment self-contact --shard i/n` (each DIR holds one shard's
// experiment.json) into DIR2/experiment.json and DIR2/experiment.md, byte for byte what the
// unsharded run writes (comparisons/suites/merge.h). Inconsistent shards (a different n, a
// shard given twice or missing, a run twice or missing, other settings): one line, exit 2.
#include "comparisons/cli/commands.h"
#include "comparisons/io/atomic_file.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/experiment_self_contact.h"
#include "comparisons/suites/merge.h"

#include <filesystem>
#include <iostream>
#include <memory>

namespace tecido::cli {

namespace {

Command add_merge(CLI::App& app) {
  struct Opts {
    std::vector<std::string> dirs;
    std::string out, seed_table;
  };
  auto o = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand("merge", "Join the shards of `experiment self-contact --shard i/n` into one result");
  sub->add_option("dirs", o->dirs, "The shards' output directories (or their experiment.json files)")->required();
  sub->add_option("--out", o->out, "Output directory (experiment.json, experiment.md)")->required();
  sub->add_option("--seed-table", o->seed_table, "The seed's tables (default: the path recorded in the shards)");
  return [o]() {
    std::vector<std::string> files;
    for (const auto& d : o->dirs) {
      std::error_code ec;
      files.push_back(std::filesystem::is_regular_file(d, ec) ? d : (std::filesystem::path(d) / "experiment.json").string());
    }
    const suites::MergedSelfContact m = suites::merge_self_contact_shards(files);
    const io::Json seed = io::read_json_file(o->seed_table.empty() ? m.opt.seed_table_path : o->seed_table);
    io::write_file_atomic(o->out + "/experiment.json", suites::self_contact_json(m.results, m.opt));
    io::write_file_atomic(o->out + "/experiment.md", suites::self_contact_markdown(m.results, seed, m.opt));
    std::cout << "merge: " << m.shards << " shards, " << m.results.size() << " runs; wrote " << o->out
              << "/experiment.json and experiment.md\n";
    return 0;
  };
}

}  // namespace

TECIDO_REGISTER_COMMAND(merge, add_merge);

}  // namespace tecido::cli
