// tecido tritri --pairs FILE.json [--engines a,b] --json
#include "comparisons/cli/commands.h"
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
  };
  auto o = std::make_shared<Opts>();
  std::string all;
  for (const auto& e : tri_tri_engines()) all += (all.empty() ? "" : ",") + e.name;
  o->engines = all;
  CLI::App* sub = app.add_subcommand("tritri", "Triangle-triangle intersection per engine (closed triangles)");
  sub->add_option("--pairs", o->pairs, "Pairs file {\"pairs\":[{\"id\",\"a\":[[..]x3],\"b\":[[..]x3]}]}")->required()->check(non_empty());
  sub->add_option("--engines", o->engines, "Comma-separated engines (" + all + ")")->capture_default_str();
  sub->add_flag("--json", o->json, "Print JSON (the only output format; kept for the contract)");
  return [o]() {
    std::vector<std::string> known;
    for (const auto& e : tri_tri_engines()) known.push_back(e.name);
    const auto names = parse_engine_list(o->engines, known, "tritri");
    const auto pairs = io::load_tri_pairs(o->pairs);
    io::Json results = io::Json::array();
    for (const auto& p : pairs) {
      io::Json row{{"id", p.id}};
      for (const auto& name : names) {
        const auto r = find_tri_tri_engine(name)->test(p.a, p.b);
        row[name] = r ? io::Json(*r) : io::Json(nullptr);
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
