#pragma once
/// What a scene asks of cloth self-collision (scene key `self_collision`): detection every
/// `every` steps and one response (seed section 3.1.3):
///   none       detect and count only
///   gia        global intersection analysis (gia.h, Baraff, Witkin, Kass 2003)
///   edge1/2/3  the seed's edge modes 1, 2, 3 (edge_response.h, fig. 20)
///   gia+edge3  GIA, with edge mode 3 on the pairs GIA cannot resolve
///   impulse    an inelastic impulse at each contact's time of impact (continuous_impulse.h,
///              Bridson, Fedkiw, Anderson 2002, section 7.1); continuous detection only
/// `strength` is the force [N] each pushed particle receives for one step (a velocity change
/// strength * dt / m), like the wind, a force per particle (not used by none and impulse).
///
/// Detection (self_collision_response.h):
///   discrete    (the default) the intersecting triangle pairs of the current frame (self_collision.h);
///   continuous  the vertex-face and edge-edge pairs that touch while the mesh moves linearly from
///               the previous check's positions to the current ones (continuous_self_collision.h):
///               a sheet passing through another within one step is seen. The edge modes act on
///               the triangles of those contacts (contact_triangles.h); GIA is given those of
///               them that intersect at the current positions (an intersection made during the
///               interval; one that already existed and is not touched again is not re-detected).
#include <optional>
#include <string>

namespace tecido {

enum class SelfCollisionResponse { None, Gia, Edge1, Edge2, Edge3, GiaEdge3, Impulse };
enum class SelfCollisionDetection { Discrete, Continuous };

struct SelfCollisionSettings {
  SelfCollisionResponse response = SelfCollisionResponse::None;
  SelfCollisionDetection detection = SelfCollisionDetection::Discrete;
  double strength = 0.0;  ///< [N] per pushed particle
  int every = 1;          ///< detect (and respond) after every `every`-th step
  /// impulse: rounds of detection and impulses per check (each round detects again on the
  /// corrected positions; stops early when a round finds nothing to change).
  int impulse_iterations = 16;
  /// Threads the detection runs on (not a scene key: `tecido run --threads`); the pairs found do
  /// not depend on it (SelfCollisionDetector::set_threads, ContinuousSelfCollisionDetector::set_threads).
  int threads = 1;
};

/// "none", "gia", "edge1", "edge2", "edge3", "gia+edge3", "impulse".
inline const char* self_collision_response_name(SelfCollisionResponse r) {
  switch (r) {
    case SelfCollisionResponse::None: return "none";
    case SelfCollisionResponse::Gia: return "gia";
    case SelfCollisionResponse::Edge1: return "edge1";
    case SelfCollisionResponse::Edge2: return "edge2";
    case SelfCollisionResponse::Edge3: return "edge3";
    case SelfCollisionResponse::GiaEdge3: return "gia+edge3";
    case SelfCollisionResponse::Impulse: return "impulse";
  }
  return "none";
}

/// Parses the names above; nothing for an unknown name.
inline std::optional<SelfCollisionResponse> parse_self_collision_response(const std::string& s) {
  for (auto r : {SelfCollisionResponse::None, SelfCollisionResponse::Gia, SelfCollisionResponse::Edge1,
                 SelfCollisionResponse::Edge2, SelfCollisionResponse::Edge3, SelfCollisionResponse::GiaEdge3,
                 SelfCollisionResponse::Impulse})
    if (s == self_collision_response_name(r)) return r;
  return std::nullopt;
}

/// "discrete" or "continuous".
inline const char* self_collision_detection_name(SelfCollisionDetection d) {
  return d == SelfCollisionDetection::Continuous ? "continuous" : "discrete";
}

inline std::optional<SelfCollisionDetection> parse_self_collision_detection(const std::string& s) {
  if (s == "discrete") return SelfCollisionDetection::Discrete;
  if (s == "continuous") return SelfCollisionDetection::Continuous;
  return std::nullopt;
}

}  // namespace tecido
