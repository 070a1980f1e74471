#include "comparisons/cli/selfcollide_continuous.h"

#include "comparisons/cli/commands.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/obj_mesh.h"
#include "comparisons/engines/continuous_self_collision_engines.h"

#include <nlohmann/json.hpp>

#include <iostream>

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

nlohmann::ordered_json contacts_json(const ContinuousContacts& c) {
  nlohmann::ordered_json vf = nlohmann::ordered_json::array(), ee = nlohmann::ordered_json::array();
  for (const auto& p : c.vertex_face) vf.push_back({p[0], p[1]});
  for (const auto& p : c.edge_edge) ee.push_back({{p[0][0], p[0][1]}, {p[1][0], p[1][1]}});
  return {{"vertex_face", std::move(vf)}, {"edge_edge", std::move(ee)}};
}

}  // namespace

int run_selfcollide_continuous(const std::string& start, const std::string& end, const std::string& engines) {
  const auto names = parse_engine_list(engines, continuous_self_collision_engines(), "continuous self-collision");
  const io::ObjMesh m0 = io::load_obj_mesh(start), m1 = io::load_obj_mesh(end);
  check_same_mesh(m0, m1, start, end);
  for (const auto& n : names) check_continuous_self_collision_size(n, m0.triangles.size(), start);
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& n : names) out[n] = contacts_json(continuous_self_collision_contacts(n, m0.vertices, m1.vertices, m0.triangles));
  std::cout << out.dump() << "\n";
  return 0;
}

}  // namespace tecido::cli
