// tecido tritri --pairs FILE.json [--engines a,b] [--plugin PATH] [--engine-cmd NAME=CMD] --json
// Outside engines answer every pair in one batch through their door.
#include "comparisons/cli/commands.h"
#include "comparisons/cli/outside_options.h"
#include "comparisons/engines/run_engines.h"
#include "comparisons/cli/option_checks.h"
#include "comparisons/engines/tri_tri_engines.h"
#include "comparisons/io/tri_pairs.h"

#include <iostream>
#include <memory>

namespace tecido::cli {

namespace {

Command add_tritri(CLI::App& app) {
  struct Opts {
    std::string pairs, engines;
    bool json = false;
    outside::OutsideOptions outside;
  };
  auto o = std::make_shared<Opts>();
  std::string all;
  for (const auto& e : tri_tri_engines()) all += (all.empty() ? "" : ",") + e.name;
  CLI::App* sub = app.add_subcommand("tritri", "Triangle-triangle intersection per engine (closed triangles)");
  sub->add_option("--pairs", o->pairs, "Pairs file {\"pairs\":[{\"id\",\"a\":[[..]x3],\"b\":[[..]x3]}]}")->required()->check(non_empty());
  sub->add_option("--engines", o->engines,
                  "Comma-separated engines (" + all + ", and outside engines by name; default: every one)");
  sub->add_flag("--json", o->json, "Print JSON (the only output format; kept for the contract)");
  add_outside_options(sub, o->outside);
  return [o]() {
    const auto outside = load_outside_engines(o->outside);
    const auto known = tri_tri_engine_names(outside.get());
    std::string every;
    for (const auto& k : known) every += (every.empty() ? "" : ",") + k;
    const auto names = parse_engine_list(o->engines.empty() ? every : o->engines, known, "tritri");
    const auto pairs = io::load_tri_pairs(o->pairs);
    std::vector<outside::TriTriQuery> queries;
    for (const auto& p : pairs) queries.push_back({p.a, p.b});
    std::vector<std::vector<std::optional<bool>>> answers;
    for (const auto& name : names) answers.push_back(tri_tri_answers(name, queries, outside.get()));
    io::Json results = io::Json::array();
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      io::Json row{{"id", pairs[k].id}};
      for (std::size_t e = 0; e < names.size(); ++e) {
        const auto& r = answers[e][k];
        row[names[e]] = r ? io::Json(*r) : io::Json(nullptr);
      }
      results.push_back(std::move(row));
    }
    std::cout << io::Json{{"results", results}}.dump() << "\n";
    return 0;
  };
}

}  // namespace

TECIDO_REGISTER_COMMAND(tritri, add_tritri);

}  // namespace tecido::cli
