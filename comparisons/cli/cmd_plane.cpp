// tecido plane --cases FILE.json [--engines a,b] --json
#include "comparisons/cli/commands.h"
#include "comparisons/cli/option_checks.h"
#include "comparisons/engines/segment_plane_engines.h"
#include "comparisons/io/plane_cases.h"

#include <iostream>
#include <memory>

namespace tecido::cli {

namespace {

Command add_plane(CLI::App& app) {
  struct Opts {
    std::string cases, engines;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  std::string all;
  for (const auto& e : segment_plane_engines()) all += (all.empty() ? "" : ",") + e.name;
  o->engines = all;
  CLI::App* sub = app.add_subcommand("plane", "Segment vs bounded plane: hit and crossing fraction per engine");
  sub->add_option("--cases", o->cases, "Cases file {\"cases\":[{\"id\",\"plane\",\"from\",\"to\"}]}")->required()->check(non_empty());
  sub->add_option("--engines", o->engines, "Comma-separated engines (" + all + ")")->capture_default_str();
  sub->add_flag("--json", o->json, "Print JSON (the only output format; kept for the contract)");
  return [o]() {
    std::vector<std::string> known;
    for (const auto& e : segment_plane_engines()) known.push_back(e.name);
    const auto names = parse_engine_list(o->engines, known, "plane");
    const auto cases = io::load_plane_cases(o->cases);
    io::Json results = io::Json::array();
    for (const auto& c : cases) {
      io::Json row{{"id", c.id}};
      for (const auto& name : names) {
        const auto r = find_segment_plane_engine(name)->test(c.plane, c.from, c.to);
        if (!r) {
          row[name] = nullptr;
        } else {
          row[name] = {{"hit", r->hit}, {"t", r->hit ? io::Json(r->t) : io::Json(nullptr)}};
        }
      }
      results.push_back(std::move(row));
    }
    std::cout << io::Json{{"results", results}}.dump() << "\n";
    return 0;
  };
}

}  // namespace

TECIDO_REGISTER_COMMAND(plane, add_plane);

}  // namespace tecido::cli
