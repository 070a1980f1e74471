#pragma once
/// What a scene asks of cloth self-collision (scene key `self_collision`): detection every
/// `every` steps and one response (seed section 3.1.3):
///   none       detect and count only
///   gia        global intersection analysis (gia.h, Baraff, Witkin, Kass 2003)
///   edge1/2/3  the seed's edge modes 1, 2, 3 (edge_response.h, fig. 20)
///   gia+edge3  GIA, with edge mode 3 on the pairs GIA cannot resolve
/// `strength` is the force [N] each pushed particle receives for one step (a velocity change
/// strength * dt / m), like the wind, a force per particle.
#include <optional>
#include <string>

namespace tecido {

enum class SelfCollisionResponse { None, Gia, Edge1, Edge2, Edge3, GiaEdge3 };

struct SelfCollisionSettings {
  SelfCollisionResponse response = SelfCollisionResponse::None;
  double strength = 0.0;  ///< [N] per pushed particle
  int every = 1;          ///< detect (and respond) after every `every`-th step
};

/// "none", "gia", "edge1", "edge2", "edge3", "gia+edge3".
inline const char* self_collision_response_name(SelfCollisionResponse r) {
  switch (r) {
    case SelfCollisionResponse::None: return "none";
    case SelfCollisionResponse::Gia: return "gia";
    case SelfCollisionResponse::Edge1: return "edge1";
    case SelfCollisionResponse::Edge2: return "edge2";
    case SelfCollisionResponse::Edge3: return "edge3";
    case SelfCollisionResponse::GiaEdge3: return "gia+edge3";
  }
  return "none";
}

/// Parses the names above; nothing for an unknown name.
inline std::optional<SelfCollisionResponse> parse_self_collision_response(const std::string& s) {
  for (auto r : {SelfCollisionResponse::None, SelfCollisionResponse::Gia, SelfCollisionResponse::Edge1,
                 SelfCollisionResponse::Edge2, SelfCollisionResponse::Edge3, SelfCollisionResponse::GiaEdge3})
    if (s == self_collision_response_name(r)) return r;
  return std::nullopt;
}

}  // namespace tecido
