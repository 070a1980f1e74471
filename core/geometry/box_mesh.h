#pragma once
/// A box as a closed triangle mesh in its own frame (centre at the origin, half extents h): for
/// drawing it, for engines that only take meshes, and for its edges (edge contacts).
/// Corner c (0..7) is (c & 1 ? +hx : -hx, c & 2 ? +hy : -hy, c & 4 ? +hz : -hz). Triangles are
/// counter-clockwise seen from outside (their normals (b - a) x (c - a) point out), two per face in
/// the face order of segment_box.h (-x, +x, -y, +y, -z, +z).
#include "core/geometry/types.h"

#include <array>

namespace tecido {

inline std::array<Vec3, 8> box_corners(const Vec3& h) {
  std::array<Vec3, 8> c;
  for (int k = 0; k < 8; ++k) c[k] = Vec3(k & 1 ? h.x() : -h.x(), k & 2 ? h.y() : -h.y(), k & 4 ? h.z() : -h.z());
  return c;
}

inline constexpr std::array<std::array<int, 3>, 12> kBoxTriangles = {{
    {0, 4, 6}, {0, 6, 2},  // -x
    {1, 3, 7}, {1, 7, 5},  // +x
    {0, 1, 5}, {0, 5, 4},  // -y
    {2, 6, 7}, {2, 7, 3},  // +y
    {0, 2, 3}, {0, 3, 1},  // -z
    {4, 5, 7}, {4, 7, 6},  // +z
}};

/// The 12 edges as corner pairs: 4 along x, 4 along y, 4 along z.
inline constexpr std::array<std::array<int, 2>, 12> kBoxEdges = {{
    {0, 1}, {2, 3}, {4, 5}, {6, 7},
    {0, 2}, {1, 3}, {4, 6}, {5, 7},
    {0, 4}, {1, 5}, {2, 6}, {3, 7},
}};

}  // namespace tecido
