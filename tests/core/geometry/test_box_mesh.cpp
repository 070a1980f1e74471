// The box as a mesh: every triangle faces outward and lies on its face, every edge is an edge of
// the box.
#include "core/geometry/box_mesh.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

TEST(BoxMesh, TrianglesFaceOutwardOnTheirFaces) {
  const Vec3 h(1, 2, 3);
  const auto c = box_corners(h);
  for (int f = 0; f < 12; ++f) {
    const auto& t = kBoxTriangles[f];
    const Vec3 n = (c[t[1]] - c[t[0]]).cross(c[t[2]] - c[t[0]]);
    const int face = f / 2, axis = face / 2;
    const double sign = (face & 1) ? 1.0 : -1.0;
    // The normal is along the face's axis, pointing out, and every corner lies on the face.
    EXPECT_GT(sign * n[axis], 0.0) << f;
    EXPECT_EQ(n.norm(), std::abs(n[axis])) << f;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(c[t[k]][axis], sign * h[axis]) << f;
  }
}

TEST(BoxMesh, EdgesJoinCornersDifferingInOneCoordinate) {
  const auto c = box_corners(Vec3(1, 2, 3));
  for (const auto& e : kBoxEdges) {
    const Vec3 d = c[e[1]] - c[e[0]];
    EXPECT_EQ((d.array() != 0.0).count(), 1);
  }
}

}  // namespace
}  // namespace tecido
