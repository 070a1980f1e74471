#pragma once
/// Parameters of a rectangular cloth grid (seed sections 2.1, 3.1.2). The builder lives in
/// core/scene/cloth_builder.h.
#include "core/geometry/types.h"

#include <array>
#include <vector>

namespace tecido {

struct ClothGridSpec {
  int rows = 0;                       ///< particles along axis_v
  int cols = 0;                       ///< particles along axis_u
  double spacing = 0.0;               ///< distance between neighbours along an axis [m]
  Vec3 origin = Vec3::Zero();         ///< position of particle (row 0, col 0)
  Vec3 axis_u = Vec3::UnitX();        ///< unit in-plane direction of increasing col
  Vec3 axis_v = Vec3::UnitY();        ///< unit in-plane direction of increasing row
  double total_mass = 0.0;            ///< [kg], split over triangles by area, then vertices
  double stiffness_b = 0.0;           ///< type B connections (one edge apart) [N/m]
  double stiffness_a = 0.0;           ///< type A connections (two edges apart) [N/m]; 0 = none
  double damping = 0.0;               ///< spring damping [N s/m]
  double elasticity = 0.5;            ///< particle restitution quotient k
  std::vector<std::array<int, 2>> pins;  ///< (row, col) of pinned particles
};

}  // namespace tecido
