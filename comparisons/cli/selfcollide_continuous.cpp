#include "comparisons/cli/selfcollide_continuous.h"

#include "comparisons/cli/commands.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/obj_mesh.h"
#include "comparisons/engines/continuous_self_collision_engines.h"
#include "core/platform/parallel_parts.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <array>
#include <iostream>
#include <iterator>

namespace tecido::cli {

namespace {

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

/// Both frames, read side by side when two threads are allowed; an error names the first file
/// that has one, as reading them in turn would (run_parts rethrows the lowest share's).
std::array<io::ObjMesh, 2> load_frames(const std::string& start, const std::string& end, int threads) {
  std::array<io::ObjMesh, 2> m;
  const std::array<const std::string*, 2> files{&start, &end};
  const int parts = threads >= 2 ? 2 : 1;
  run_parts(parts, [&](int part) {
    for (int k = part; k < 2; k += parts) m[static_cast<std::size_t>(k)] = io::load_obj_mesh(*files[static_cast<std::size_t>(k)]);
  });
  return m;
}

}  // namespace

int run_selfcollide_continuous(const std::string& start, const std::string& end, const std::string& engines, int threads) {
  const auto names = parse_engine_list(engines, continuous_self_collision_engines(), "continuous self-collision");
  const std::array<io::ObjMesh, 2> frames = load_frames(start, end, threads);
  const io::ObjMesh &m0 = frames[0], &m1 = frames[1];
  check_same_mesh(m0, m1, start, end);
  for (const auto& n : names) check_continuous_self_collision_size(n, m0.triangles.size(), start);
  std::cout << "{";
  for (std::size_t k = 0; k < names.size(); ++k) {
    std::cout << (k ? "," : "") << nlohmann::json(names[k]).dump() << ":";
    print_contacts(continuous_self_collision_contacts(names[k], m0.vertices, m1.vertices, m0.triangles, threads));
  }
  std::cout << "}\n";
  return 0;
}

}  // namespace tecido::cli
