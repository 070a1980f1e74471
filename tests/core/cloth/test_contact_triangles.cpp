// core/cloth/contact_triangles.h: the triangle pairs of continuous contacts, hand-worked on a
// 3 x 3 grid of the cloth builder (2 x 2 squares, 8 triangles).
#include "core/cloth/contact_triangles.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

// Vertices r * 3 + c; square (r, c) gives triangles 2k = (a, b, d) and 2k + 1 = (a, d, e) with
// a = (r, c), b = (r, c + 1), d = (r + 1, c + 1), e = (r + 1, c), k = 2 r + c (cloth_builder.cpp).
const std::vector<std::array<int, 3>> kTris = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4},
                                               {3, 4, 7}, {3, 7, 6}, {4, 5, 8}, {4, 8, 7}};

TEST(ContactTriangles, IncidentTrianglesPerVertex) {
  const VertexTriangles vt = build_vertex_triangles(9, kTris);
  auto of = [&](int v) { return std::vector<int>(vt.tris.begin() + vt.start[v], vt.tris.begin() + vt.start[v + 1]); };
  EXPECT_EQ(of(0), (std::vector<int>{0, 1}));
  EXPECT_EQ(of(4), (std::vector<int>{0, 1, 3, 4, 6, 7}));
  EXPECT_EQ(of(2), (std::vector<int>{2}));
  EXPECT_EQ(of(8), (std::vector<int>{6, 7}));
}

TEST(ContactTriangles, VertexFaceAndEdgeEdgeContactsMapToDisjointTrianglePairs) {
  const VertexTriangles vt = build_vertex_triangles(9, kTris);
  std::vector<TrianglePair> out;
  // Vertex 0 against face 6 = (4, 5, 8): vertex 0's triangles are 0 and 1, both with vertex 4.
  ContinuousContacts c;
  c.vertex_face = {{0, 6}};
  contact_triangle_pairs(c, kTris, vt, out);
  EXPECT_TRUE(out.empty());
  // Vertex 2 against face 5 = (3, 7, 6): vertex 2's only triangle, 2 = (1, 2, 5), shares none.
  c.vertex_face = {{2, 5}};
  contact_triangle_pairs(c, kTris, vt, out);
  EXPECT_EQ(out, (std::vector<TrianglePair>{{2, 5}}));
  // Edge (0, 1) against edge (7, 8): (0, 1) is in triangle 0 only, (7, 8) in triangle 7 only;
  // triangle 0 = (0, 1, 4) and 7 = (4, 8, 7) share vertex 4: no pair. Edge (1, 2) (triangle 2)
  // against (6, 7) (triangle 5): disjoint, the pair (2, 5); listed once with the vertex contact.
  c.vertex_face = {{2, 5}};
  c.edge_edge = {EdgeEdgePair{MeshEdge{0, 1}, MeshEdge{7, 8}}, EdgeEdgePair{MeshEdge{1, 2}, MeshEdge{6, 7}}};
  contact_triangle_pairs(c, kTris, vt, out);
  EXPECT_EQ(out, (std::vector<TrianglePair>{{2, 5}}));
  // Edge (1, 5) (triangles 2 = (1, 2, 5) and 3 = (1, 5, 4)) against (3, 6) (triangle 5 only):
  // (2, 5) and (3, 5).
  c.vertex_face.clear();
  c.edge_edge = {EdgeEdgePair{MeshEdge{1, 5}, MeshEdge{3, 6}}};
  contact_triangle_pairs(c, kTris, vt, out);
  EXPECT_EQ(out, (std::vector<TrianglePair>{{2, 5}, {3, 5}}));
}

}  // namespace
}  // namespace tecido
