// tecido selfcollide --mesh FILE.obj [--to END.obj] [--engines core,core-brute,...] [--threads N] --json
// Prints {"<engine>":[[i,j],...], ...}: the intersecting pairs of triangles sharing no vertex,
// i < j, in the OBJ's triangle numbering (comparisons/io/obj_mesh.h), per engine, in the order
// the engines are named; null when an engine cannot answer. The engines that test every pair
// (core-brute, exact) take at most io::kMaxBruteForceTriangles triangles; the answer is printed
// as it is produced (no document of it is built).
#include "comparisons/cli/commands.h"
#include "comparisons/cli/option_checks.h"
#include "comparisons/cli/selfcollide_continuous.h"
#include "comparisons/engines/self_collision_engines.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"
#include "comparisons/io/obj_mesh.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <thread>

namespace tecido::cli {

namespace {

/// `"name":[[i,j],...]` or `"name":null`, written as it goes.
void print_engine(const std::string& name, const std::optional<std::vector<TrianglePair>>& pairs) {
  std::cout << nlohmann::json(name).dump() << ":";
  if (!pairs) {
    std::cout << "null";
    return;
  }
  std::string chunk = "[";
  for (std::size_t k = 0; k < pairs->size(); ++k) {
    chunk += fmt::format("{}[{},{}]", k ? "," : "", (*pairs)[k][0], (*pairs)[k][1]);
    if (chunk.size() > (1u << 16)) {
      std::cout << chunk;
      chunk.clear();
    }
  }
  std::cout << chunk << "]";
}

Command add_selfcollide(CLI::App& app) {
  struct Opts {
    std::string mesh, to, engines;
    int threads = 0;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  std::string all;
  for (const auto& e : self_collision_engines()) all += (all.empty() ? "" : ",") + e.name;
  o->engines = "core";
  CLI::App* sub = app.add_subcommand("selfcollide", "Intersecting triangle pairs of a mesh (self-collision) per engine");
  sub->add_option("--mesh", o->mesh, "Triangle mesh (Wavefront OBJ: v and f records)")->required()->check(non_empty());
  sub->add_option("--engines", o->engines, "Comma-separated engines (" + all + ")")->capture_default_str();
  sub->add_option("--to", o->to,
                  "Second frame of the same mesh (same faces): the vertex-face and edge-edge pairs touching while it "
                  "moves linearly from --mesh to --to, {\"<engine>\":{\"vertex_face\":[[v,f]],\"edge_edge\":"
                  "[[[a,b],[c,d]]]}}; engines core (exact answer), core-brute (core's test on every pair), exact");
  sub->add_option("--threads", o->threads,
                  "Worker threads of core's continuous detection and the referee's confirmation (with --to; 0 = all "
                  "cores); results do not depend on it")
      ->check(integer_in(0, io::kMaxThreads));
  sub->add_flag("--json", o->json, "Print JSON (the only output format; kept for the contract)");
  return [o]() {
    const int threads = o->threads > 0 ? o->threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    if (!o->to.empty()) return run_selfcollide_continuous(o->mesh, o->to, o->engines, threads);
    std::vector<std::string> known;
    for (const auto& e : self_collision_engines()) known.push_back(e.name);
    const auto names = parse_engine_list(o->engines, known, "self-collision");
    const io::ObjMesh mesh = io::load_obj_mesh(o->mesh);
    for (const auto& name : names) check_self_collision_size(name, mesh.triangles.size(), o->mesh);
    std::cout << "{";
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (k) std::cout << ",";
      print_engine(names[k], find_self_collision_engine(names[k])->pairs(mesh.vertices, mesh.triangles));
    }
    std::cout << "}\n";
    return 0;
  };
}

}  // namespace

TECIDO_REGISTER_COMMAND(selfcollide, add_selfcollide);

}  // namespace tecido::cli
