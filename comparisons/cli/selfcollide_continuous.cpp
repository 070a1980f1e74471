#include "comparisons/cli/selfcollide_continuous.h"

#include "comparisons/cli/commands.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/obj_mesh.h"
#include "core/cloth/continuous_self_collision.h"
#include "reference/exact_ccd.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <iostream>
#include <iterator>

namespace tecido::cli {

namespace {

CcdAnswer exact_test(const CcdQuery& q) { return reference::to_ccd_answer(reference::exact_ccd(q)); }

/// The two frames must be one mesh: same vertex count, same triangles in the same order.
void check_same_mesh(const io::ObjMesh& a, const io::ObjMesh& b, const std::string& start, const std::string& end) {
  if (a.vertices.size() != b.vertices.size())
    throw io::UsageError("--to " + end + ": " + std::to_string(b.vertices.size()) + " vertices, but --mesh " + start +
                         " has " + std::to_string(a.vertices.size()) + " (the frames must be one mesh: same vertices, same faces)");
  if (a.triangles.size() != b.triangles.size())
    throw io::UsageError("--to " + end + ": " + std::to_string(b.triangles.size()) + " triangles, but --mesh " + start +
                         " has " + std::to_string(a.triangles.size()) + " (the frames must have the same faces)");
  for (std::size_t k = 0; k < a.triangles.size(); ++k)
    if (a.triangles[k] != b.triangles[k])
      throw io::InputError(end, "line " + std::to_string(b.triangle_line[k]),
                           "triangle " + std::to_string(k) + " differs from " + start + "'s (line " +
                               std::to_string(a.triangle_line[k]) + "): the frames must have the same faces");
}

void check_size(const std::string& engine, std::size_t triangles, std::size_t limit, const std::string& file) {
  if (triangles > limit)
    throw io::UsageError("--engines: " + engine + " tests every pair and takes at most " + std::to_string(limit) +
                         " triangles, but " + file + " has " + std::to_string(triangles) + " (use core)");
}

ContinuousContacts run_engine(const std::string& name, const io::ObjMesh& m0, const io::ObjMesh& m1, int threads) {
  const auto& x0 = m0.vertices;
  const auto& x1 = m1.vertices;
  const auto& tris = m0.triangles;
  if (name == "core-brute") return continuous_self_collision_brute(x0, x1, tris);
  if (name == "exact") return continuous_self_collision_brute(x0, x1, tris, &exact_test);
  ContinuousSelfCollisionDetector det(tris, x0);
  det.set_threads(threads);
  const ContinuousContacts& candidates = det.detect(x0, x1);
  // The referee's filter decides nearly every candidate; exact arithmetic only where it cannot.
  return filter_contacts(candidates, x0, x1, tris, &reference::exact_ccd_hit, threads);
}

/// `{"vertex_face":[[v,f],...],"edge_edge":[[[a,b],[c,d]],...]}`, written as it goes (no
/// document of it is built: a large mesh's answer has hundreds of thousands of pairs).
void print_contacts(const ContinuousContacts& c) {
  std::string chunk = "{\"vertex_face\":[";
  const auto spill = [&chunk] {
    if (chunk.size() < (1u << 16)) return;
    std::cout << chunk;
    chunk.clear();
  };
  for (std::size_t k = 0; k < c.vertex_face.size(); ++k) {
    fmt::format_to(std::back_inserter(chunk), "{}[{},{}]", k ? "," : "", c.vertex_face[k][0], c.vertex_face[k][1]);
    spill();
  }
  chunk += "],\"edge_edge\":[";
  for (std::size_t k = 0; k < c.edge_edge.size(); ++k) {
    const EdgeEdgePair& p = c.edge_edge[k];
    fmt::format_to(std::back_inserter(chunk), "{}[[{},{}],[{},{}]]", k ? "," : "", p[0][0], p[0][1], p[1][0], p[1][1]);
    spill();
  }
  std::cout << chunk << "]}";
}

}  // namespace

const std::vector<std::string>& continuous_selfcollide_engines() {
  static const std::vector<std::string> names = {"core", "core-brute", "exact"};
  return names;
}

int run_selfcollide_continuous(const std::string& start, const std::string& end, const std::string& engines, int threads) {
  const auto names = parse_engine_list(engines, continuous_selfcollide_engines(), "continuous self-collision");
  const io::ObjMesh m0 = io::load_obj_mesh(start), m1 = io::load_obj_mesh(end);
  check_same_mesh(m0, m1, start, end);
  for (const auto& n : names) {
    if (n == "core-brute") check_size(n, m0.triangles.size(), kMaxBruteForceTriangles, start);
    if (n == "exact") check_size(n, m0.triangles.size(), kMaxExactContinuousTriangles, start);
  }
  std::cout << "{";
  for (std::size_t k = 0; k < names.size(); ++k) {
    std::cout << (k ? "," : "") << nlohmann::json(names[k]).dump() << ":";
    print_contacts(run_engine(names[k], m0, m1, threads));
  }
  std::cout << "}\n";
  return 0;
}

}  // namespace tecido::cli
