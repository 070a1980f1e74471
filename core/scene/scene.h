#pragma once
/// The scene model: everything a simulation needs, in SI units. A scene models only what it
/// names (docs/design.md section 4): optional parts that are absent cost nothing. Loading from JSON
/// lives in comparisons/io (core depends on Eigen alone).
#include "core/cloth/cloth_grid.h"
#include "core/cloth/self_collision_settings.h"
#include "core/dynamics/force_model.h"
#include "core/dynamics/integrator.h"
#include "core/dynamics/particles.h"
#include "core/dynamics/plane_contact.h"
#include "core/geometry/bounded_plane.h"
#include "core/geometry/obstacle.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tecido {

struct Scene {
  IntegratorKind integrator = IntegratorKind::Symplectic;
  double dt = 0.01;
  long long steps = 0;
  std::uint64_t seed = 0;  ///< drives every random choice (e.g. a swirl's phase)

  Particles particles;
  ForceModel forces;
  std::vector<BoundedPlane> planes;
  /// Spheres, boxes and triangle meshes, static or moving (core/geometry/obstacle.h).
  std::vector<Obstacle> obstacles;
  /// Whether springs are tested against the obstacles' edges (box edges, mesh feature edges), not
  /// only particles against their faces (core/dynamics/edge_contacts.h). Off by default, as in
  /// the seed's engine.
  bool edge_contacts = false;
  ContactSettings contact;

  /// Cloth parameters, when the scene has a cloth (its particles and springs are appended to
  /// `particles` and `forces.springs` by the builder; `triangles` holds its mesh).
  std::optional<ClothGridSpec> cloth;
  /// Index of the first cloth particle in `particles`.
  int cloth_first_particle = 0;
  /// Triangle mesh over particle indices (the cloth's), in the builder's documented order.
  std::vector<std::array<int, 3>> triangles;
  /// Self-collision detection and response over `triangles`, when the scene asks for it
  /// (core/simulation/self_collision_response.h installs it as the simulation's post_step hook).
  std::optional<SelfCollisionSettings> self_collision;
};

}  // namespace tecido
