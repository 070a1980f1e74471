#pragma once
/// Builds a rectangular mass-spring cloth (seed sections 2.1, 3.1.2) into a Scene.
///
/// Numbering (stable; the Bullet adapter mirrors it):
///  - particle (row r, col c) is scene.cloth_first_particle + r * cols + c, at
///    origin + c * spacing * axis_u + r * spacing * axis_v;
///  - quad (r, c), r < rows-1, c < cols-1, in row-major order, holds triangles 2q and 2q+1
///    (q = r * (cols-1) + c) with corners a=(r,c), b=(r,c+1), d=(r+1,c+1), e=(r+1,c):
///    triangle 2q = (a, b, d), triangle 2q+1 = (a, d, e); both counter-clockwise about
///    axis_u x axis_v.
///  - springs in this order: type B (one edge apart) horizontal, vertical, diagonal (a-d),
///    anti-diagonal (b-e); then type A (two edges apart) horizontal, vertical, diagonal,
///    anti-diagonal; each family row-major. Rest length = initial distance.
/// Mass: total_mass split over the triangles by area, each triangle's share split equally
/// over its three vertices. Pinned particles keep no mass (inverse mass 0).
#include "core/scene/scene.h"

namespace tecido {

/// Appends the cloth described by `spec` to scene (particles, springs, triangles) and records
/// spec in scene.cloth. Preconditions (validated by the scene reader): rows, cols >= 2,
/// spacing > 0, total_mass > 0, axes unit and orthogonal, pins inside the grid.
void append_cloth(Scene& scene, const ClothGridSpec& spec);

/// The unit square cloth of the benchmarks and kernel tests: n x n nodes (n >= 2) spanning
/// 1 m along axis_u and axis_v from the origin, total mass 1 kg, stiffness_b 1, nothing pinned.
inline ClothGridSpec unit_square_cloth(int n) {
  ClothGridSpec spec;
  spec.rows = spec.cols = n;
  spec.spacing = 1.0 / (n - 1);
  spec.total_mass = 1.0;
  spec.stiffness_b = 1.0;
  return spec;
}

/// Particle index of grid node (r, c) for a cloth whose first particle is `first`.
inline int cloth_node(const ClothGridSpec& spec, int first, int r, int c) { return first + r * spec.cols + c; }

}  // namespace tecido
