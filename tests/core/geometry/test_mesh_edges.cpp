// Feature edges of a mesh: a box split into 12 triangles has its 12 edges and none of the six
// face diagonals; an open mesh keeps its border; a fold keeps its crease.
#include "core/geometry/mesh_edges.h"

#include "core/geometry/box_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace tecido {
namespace {

TEST(MeshEdges, BoxMeshHasExactlyTheBoxEdges) {
  const auto c = box_corners(Vec3(1, 2, 3));
  const std::vector<Vec3> v(c.begin(), c.end());
  const std::vector<std::array<int, 3>> t(kBoxTriangles.begin(), kBoxTriangles.end());
  const auto edges = mesh_feature_edges(v, t);
  ASSERT_EQ(edges.size(), 12u);
  for (const auto& e : kBoxEdges) {
    const std::array<int, 2> sorted{std::min(e[0], e[1]), std::max(e[0], e[1])};
    EXPECT_NE(std::find(edges.begin(), edges.end(), sorted), edges.end()) << e[0] << "-" << e[1];
  }
}

TEST(MeshEdges, FlatSquareKeepsItsBorderFoldKeepsItsCrease) {
  const std::vector<Vec3> v = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  const std::vector<std::array<int, 3>> t = {{0, 1, 2}, {0, 2, 3}};
  const auto flat = mesh_feature_edges(v, t);
  EXPECT_EQ(flat, (std::vector<std::array<int, 2>>{{0, 1}, {0, 3}, {1, 2}, {2, 3}}));  // the diagonal 0-2 is gone
  std::vector<Vec3> folded = v;
  folded[3] = Vec3(0, 1, 0.5);  // the second triangle tilted about the diagonal
  EXPECT_EQ(mesh_feature_edges(folded, t).size(), 5u);
}

}  // namespace
}  // namespace tecido
