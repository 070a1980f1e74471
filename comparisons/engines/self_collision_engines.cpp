#include "comparisons/engines/self_collision_engines.h"

namespace tecido {

namespace {
std::optional<std::vector<TrianglePair>> core_pairs(const std::vector<Vec3>& v, const std::vector<std::array<int, 3>>& t) {
  return self_collision_pairs(v, t);
}
std::optional<std::vector<TrianglePair>> core_brute_pairs(const std::vector<Vec3>& v,
                                                          const std::vector<std::array<int, 3>>& t) {
  return self_collision_pairs_brute(v, t);
}
}  // namespace

const std::vector<SelfCollisionEngine>& self_collision_engines() {
  static const std::vector<SelfCollisionEngine> engines = {
      {"core", &core_pairs},
      {"core-brute", &core_brute_pairs},
  };
  return engines;
}

const SelfCollisionEngine* find_self_collision_engine(const std::string& name) {
  for (const auto& e : self_collision_engines())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace tecido
