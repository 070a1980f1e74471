// tecido selfcollide --mesh FILE.obj [--engines core,core-brute,...] --json
// Prints {"<engine>":[[i,j],...], ...}: the intersecting pairs of triangles sharing no vertex,
// i < j, in the OBJ's triangle numbering (comparisons/io/obj_mesh.h), per engine, in the order
// the engines are named; null when an engine cannot answer.
#include "comparisons/cli/commands.h"
#include "comparisons/cli/selfcollide_continuous.h"
#include "comparisons/engines/self_collision_engines.h"
#include "comparisons/io/obj_mesh.h"

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

namespace tecido::cli {

namespace {

Command add_selfcollide(CLI::App& app) {
  struct Opts {
    std::string mesh, to, engines;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  std::string all;
  for (const auto& e : self_collision_engines()) all += (all.empty() ? "" : ",") + e.name;
  o->engines = "core";
  CLI::App* sub = app.add_subcommand("selfcollide", "Intersecting triangle pairs of a mesh (self-collision) per engine");
  sub->add_option("--mesh", o->mesh, "Triangle mesh (Wavefront OBJ: v and f records)")->required();
  sub->add_option("--engines", o->engines, "Comma-separated engines (" + all + ")")->capture_default_str();
  sub->add_option("--to", o->to,
                  "Second frame of the same mesh (same faces): the vertex-face and edge-edge pairs touching while it "
                  "moves linearly from --mesh to --to, {\"<engine>\":{\"vertex_face\":[[v,f]],\"edge_edge\":"
                  "[[[a,b],[c,d]]]}}; engines core (exact answer), core-brute (core's test on every pair), exact");
  sub->add_flag("--json", o->json, "Print JSON (the only output format; kept for the contract)");
  return [o]() {
    if (!o->to.empty()) return run_selfcollide_continuous(o->mesh, o->to, o->engines);
    std::vector<std::string> known;
    for (const auto& e : self_collision_engines()) known.push_back(e.name);
    const auto names = parse_engine_list(o->engines, known, "self-collision");
    const io::ObjMesh mesh = io::load_obj_mesh(o->mesh);
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    for (const auto& name : names) {
      const auto pairs = find_self_collision_engine(name)->pairs(mesh.vertices, mesh.triangles);
      if (!pairs) {
        out[name] = nullptr;
        continue;
      }
      nlohmann::ordered_json list = nlohmann::ordered_json::array();
      for (const auto& p : *pairs) list.push_back({p[0], p[1]});
      out[name] = std::move(list);
    }
    std::cout << out.dump() << "\n";
    return 0;
  };
}

}  // namespace

TECIDO_REGISTER_COMMAND(selfcollide, add_selfcollide);

}  // namespace tecido::cli
