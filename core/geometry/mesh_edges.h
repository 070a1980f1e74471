#pragma once
/// The edges of a triangle mesh that a spring can catch on: every edge used by one triangle only
/// (a border) or by two or more triangles that are not coplanar (a crease, ridge or valley).
/// Edges between coplanar triangles (a flat face split in two) are left out: a spring lying on
/// the face touches them all the time and they are no obstacle. Coplanarity is exact
/// (orient3d_sign of a triangle's corners and the other triangle's far corner).
#include "core/geometry/types.h"

#include <array>
#include <vector>

namespace tecido {

/// Feature edges as vertex pairs (smaller index first), sorted.
std::vector<std::array<int, 2>> mesh_feature_edges(const std::vector<Vec3>& vertices,
                                                   const std::vector<std::array<int, 3>>& triangles);

}  // namespace tecido
