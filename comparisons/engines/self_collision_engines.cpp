#include "comparisons/engines/self_collision_engines.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"
#include "reference/exact_referee.h"
#include "reference/fcl_adapter.h"

namespace tecido {

namespace {
std::optional<std::vector<TrianglePair>> core_pairs(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& t) {
  return self_collision_pairs(v, t);
}
std::optional<std::vector<TrianglePair>> core_brute_pairs(const std::vector<Vec3>& v,
                                                          const std::vector<std::array<int, 3>>& t) {
  return self_collision_pairs_brute(v, t);
}
std::optional<std::vector<TrianglePair>> fcl_pairs(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& t) {
  std::vector<TrianglePair> out;
  for (const auto& [i, j] : reference::fcl_self_collision(v, t)) out.push_back({i, j});
  return out;
}
std::optional<std::vector<TrianglePair>> exact_pairs(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& t) {
  return self_collision_pairs_brute(v, t, &reference::exact_tri_tri);
}

}  // namespace

const std::vector<SelfCollisionEngine>& self_collision_engines() {
  static const std::vector<SelfCollisionEngine> engines = {
      {"core", &core_pairs},
      {"core-brute", &core_brute_pairs},
      {"fcl", &fcl_pairs},
      {"exact", &exact_pairs},  // brute force with CGAL's exact triangle test
  };
  return engines;
}

const SelfCollisionEngine* find_self_collision_engine(const std::string& name) {
  for (const auto& e : self_collision_engines())
    if (e.name == name) return &e;
  return nullptr;
}

void check_self_collision_size(const std::string& engine, std::size_t triangles, const std::string& mesh,
                               const std::string& option) {
  const bool every_pair = engine == "core-brute" || engine == "exact";
  if (every_pair && triangles > io::kMaxBruteForceTriangles)
    throw io::UsageError(option + ": " + engine + " tests every pair of triangles and takes at most " +
                         std::to_string(io::kMaxBruteForceTriangles) + ", but " + mesh + " has " +
                         std::to_string(triangles) + " (use core or fcl)");
}

}  // namespace tecido
