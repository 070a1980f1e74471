#pragma once
/// The public self-collision functions' arguments (tecido::core::self_collisions and
/// continuous_self_collisions in include/tecido/core.h, tecido::referee::continuous_self_collisions
/// in include/tecido/referee.h), checked the same way: "<function>: <problem>", std::domain_error for a
/// non-finite coordinate (as the referee's other functions), std::invalid_argument otherwise.
/// And core's contact lists as the public SelfContacts.
#include "core/cloth/continuous_self_collision.h"

#include <tecido/geometry.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace tecido::api {

/// Finite vertices, and faces of three distinct indices in [0, V.size()).
inline void check_mesh(const char* function, const std::vector<Vec3>& V, const Faces& F, const char* vertices = "V") {
  for (std::size_t i = 0; i < V.size(); ++i)
    if (!V[i].allFinite())
      throw std::domain_error(std::string(function) + ": " + vertices + "[" + std::to_string(i) + "] is not finite");
  const long long n = static_cast<long long>(V.size());
  for (std::size_t f = 0; f < F.size(); ++f) {
    const auto& t = F[f];
    for (int k = 0; k < 3; ++k)
      if (t[k] < 0 || t[k] >= n)
        throw std::invalid_argument(std::string(function) + ": F[" + std::to_string(f) + "] names vertex " +
                                    std::to_string(t[k]) + ", outside [0, " + std::to_string(n) + ")");
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      throw std::invalid_argument(std::string(function) + ": F[" + std::to_string(f) + "] repeats a vertex");
  }
}

/// Two frames of one mesh: both checked, and the same vertex count.
inline void check_motion_mesh(const char* function, const std::vector<Vec3>& V0, const std::vector<Vec3>& V1,
                              const Faces& F) {
  if (V0.size() != V1.size())
    throw std::invalid_argument(std::string(function) + ": V1 has " + std::to_string(V1.size()) + " vertices, V0 " +
                                std::to_string(V0.size()) + " (the frames must be one mesh)");
  check_mesh(function, V0, F, "V0");
  check_mesh(function, V1, F, "V1");
}

inline SelfContacts self_contacts(const ContinuousContacts& c) { return SelfContacts{c.vertex_face, c.edge_edge}; }

}  // namespace tecido::api
