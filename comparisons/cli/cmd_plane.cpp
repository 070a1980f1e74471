// tecido plane --cases FILE.json [--engines a,b] [--plugin PATH] [--engine-cmd NAME=CMD] --json
// Outside engines answer every case in one batch through their door.
#include "comparisons/cli/commands.h"
#include "comparisons/cli/outside_options.h"
#include "comparisons/engines/run_engines.h"
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
    outside::OutsideOptions outside;
  };
  auto o = std::make_shared<Opts>();
  std::string all;
  for (const auto& e : segment_plane_engines()) all += (all.empty() ? "" : ",") + e.name;
  CLI::App* sub = app.add_subcommand("plane", "Segment vs bounded plane: hit and crossing fraction per engine");
  sub->add_option("--cases", o->cases, "Cases file {\"cases\":[{\"id\",\"plane\",\"from\",\"to\"}]}")->required()->check(non_empty());
  sub->add_option("--engines", o->engines,
                  "Comma-separated engines (" + all + ", and outside engines by name; default: every one)");
  sub->add_flag("--json", o->json, "Print JSON (the only output format; kept for the contract)");
  add_outside_options(sub, o->outside);
  return [o]() {
    const auto outside = load_outside_engines(o->outside);
    const auto known = segment_plane_engine_names(outside.get());
    std::string every;
    for (const auto& k : known) every += (every.empty() ? "" : ",") + k;
    const auto names = parse_engine_list(o->engines.empty() ? every : o->engines, known, "plane");
    const auto cases = io::load_plane_cases(o->cases);
    std::vector<outside::SegmentPlaneQuery> queries;
    for (const auto& c : cases) queries.push_back({c.plane, c.from, c.to});
    std::vector<std::vector<std::optional<SegmentPlaneHit>>> answers;
    for (const auto& name : names) answers.push_back(segment_plane_answers(name, queries, outside.get()));
    io::Json results = io::Json::array();
    for (std::size_t k = 0; k < cases.size(); ++k) {
      io::Json row{{"id", cases[k].id}};
      for (std::size_t e = 0; e < names.size(); ++e) {
        const auto& r = answers[e][k];
        if (!r) row[names[e]] = nullptr;
        else row[names[e]] = {{"hit", r->hit}, {"t", r->hit ? io::Json(r->t) : io::Json(nullptr)}};
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
