#pragma once
/// How both Bullet adapters stand in for a bounded plane: a static box (btStaticPlaneShape cannot
/// be bounded) whose front face is the plane itself, lying behind it on the side away from every
/// free particle. Only core types here; the adapters turn it into a btBoxShape.
#include "core/scene/scene.h"

#include <array>
#include <cstddef>
#include <string>

namespace tecido::reference {

struct PlaneBox {
  Vec3 centre = Vec3::Zero();        ///< box centre [m]
  Vec3 half_extents = Vec3::Zero();  ///< along forward, right, normal [m]
  std::array<Vec3, 3> axes;          ///< forward, right, normal: the box's local x, y, z
  double shape_margin = 0.0;         ///< Bullet collision margin of the box shape (kept below every half extent)
  double contact_offset = 0.0;       ///< distance from the plane at which Bullet holds a resting node [m]
  std::string note;                  ///< non-empty when the plane is not modelled exactly ("not modelled" line)
};

/// The box for scene.planes[k], `thickness` thick, with the cloth's collision margin. When free
/// particles start on both sides of the plane the box is centred on it and `note` says so.
PlaneBox plane_box(const Scene& scene, std::size_t k, double thickness, double collision_margin);

}  // namespace tecido::reference
