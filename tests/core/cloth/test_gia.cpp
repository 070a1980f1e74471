// Global intersection analysis (gia.h) on hand-built interpenetrations whose cut edges,
// regions and pulls are worked out by hand, and the seed's failing case (the intersection
// reaches the cloth's border, its curve is open, and the flood covers everything).
#include "core/cloth/gia.h"
#include "core/cloth/mesh_topology.h"
#include "core/cloth/self_collision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <set>

namespace tecido {
namespace {

struct SheetMesh {
  std::vector<Vec3> x;
  std::vector<std::array<int, 3>> tris;
};

// Appends a rows x cols sheet with the cloth builder's numbering and triangulation
// (node first + r*cols + c; quad (r,c) -> (a,b,d), (a,d,e)); pos(r, c) places the nodes.
int add_sheet(SheetMesh& m, int rows, int cols, const std::function<Vec3(int, int)>& pos) {
  const int first = static_cast<int>(m.x.size());
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) m.x.push_back(pos(r, c));
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < cols; ++c) {
      const int a = first + r * cols + c, b = a + 1, d = a + cols + 1, e = a + cols;
      m.tris.push_back({a, b, d});
      m.tris.push_back({a, d, e});
    }
  return first;
}

std::set<std::array<int, 2>> cut_edge_set(const MeshTopology& t, const GiaResult& g) {
  std::set<std::array<int, 2>> s;
  for (std::size_t e = 0; e < t.edges.size(); ++e)
    if (g.cut[e]) s.insert(t.edges[e]);
  return s;
}

std::vector<std::vector<int>> region_vertices(const GiaResult& g) {
  std::vector<std::vector<int>> out;
  for (int c : g.regions) {
    std::vector<int> vs;
    for (std::size_t v = 0; v < g.component.size(); ++v)
      if (g.component[v] == c) vs.push_back(static_cast<int>(v));
    out.push_back(vs);
  }
  return out;
}

// Sheet A: 5 x 5 nodes in the plane z = 0, node (r, c) at (c, r, 0), ids 0..24.
// Sheet B: a 3 x 3 tent, ids 25..33, node (r, c) at (1.1 + c, 1.2 + r, -0.5), its centre (id 29)
// raised to (2.1, 2.2, 0.6): it pokes up through A near A's node (2, 2) = id 12.
// By hand: the tent meets z = 0 at 0.6/1.1 of the way from the apex down each of its six
// edges, a hexagon around (2.1, 2.2) with corners (2.1, 1.655), (1.555, 2.2), (2.645, 2.2),
// (2.1, 2.745), (1.555, 1.655), (2.645, 2.745). Inside it lies A's node 12 and no other A node;
// no A edge that avoids node 12 reaches it (it spans x in [1.555, 2.645], y in [1.655, 2.745],
// y - x in [-0.445, 0.645]). So the cut edges are A's six edges at node 12 and the tent's six
// edges at its apex; the regions are {12} (A's side inside the tent) and {29} (the apex, above
// A); 12 is pulled toward the apex and the apex toward 12.
TEST(Gia, TentThroughSheetGivesHandWorkedRegions) {
  SheetMesh m;
  add_sheet(m, 5, 5, [](int r, int c) { return Vec3(c, r, 0); });
  add_sheet(m, 3, 3, [](int r, int c) { return Vec3(1.1 + c, 1.2 + r, -0.5); });
  m.x[29] = Vec3(2.1, 2.2, 0.6);
  const MeshTopology topo = build_mesh_topology(static_cast<int>(m.x.size()), m.tris);
  const auto pairs = self_collision_pairs_brute(m.x, m.tris);
  ASSERT_FALSE(pairs.empty());
  // Every intersecting pair joins a triangle at node 12 and a tent triangle at the apex.
  for (const auto& p : pairs) {
    const auto& ta = m.tris[p[0]];
    const auto& tb = m.tris[p[1]];
    EXPECT_TRUE(std::count(ta.begin(), ta.end(), 12) == 1) << p[0];
    EXPECT_TRUE(std::count(tb.begin(), tb.end(), 29) == 1) << p[1];
  }
  GiaResult g;
  analyse_intersections(m.x, m.tris, topo, pairs, g);
  const std::set<std::array<int, 2>> expected_cuts = {{7, 12},  {11, 12}, {12, 13}, {12, 17}, {6, 12},  {12, 18},
                                                      {26, 29}, {28, 29}, {29, 30}, {29, 32}, {25, 29}, {29, 33}};
  EXPECT_EQ(cut_edge_set(topo, g), expected_cuts);
  EXPECT_EQ(g.cut_edges, 12);
  EXPECT_EQ(region_vertices(g), (std::vector<std::vector<int>>{{12}, {29}}));
  EXPECT_EQ(g.unseparated_cut_edges, 0);
  EXPECT_EQ(g.ambiguous_cut_edges, 0);
  EXPECT_EQ(g.unresolved_pairs, 0);
  const Vec3 up = (Vec3(2.1, 2.2, 0.6) - Vec3(2, 2, 0)).normalized();
  EXPECT_LT((g.pull[g.component[12]] - up).norm(), 1e-15);
  EXPECT_LT((g.pull[g.component[29]] + up).norm(), 1e-15);
}

// The seed's failing case: two sheets that cross like two slotted cards, each one's border
// passing through the other's interior. A: vertical, x = 0.05, y in [0, 3], z in
// [-1.55, 0.45]; B: horizontal, z = -0.05, x in [-1.5, 1.5], y in [1.6, 4.6]. They meet on the
// segment x = 0.05, z = -0.05, y in [1.6, 3]: on A it runs from A's border (y = 3) to an
// interior point, on B from B's border (y = 1.6) to an interior point. Neither curve closes,
// so no cut edge separates anything: each sheet stays one component (the flood from either
// side covers the whole sheet), no region is found, every pair is unresolved.
TEST(Gia, IntersectionReachingTheBorderIsDetectedAsFailure) {
  SheetMesh m;
  add_sheet(m, 3, 4, [](int r, int c) { return Vec3(0.05, c, 0.45 - r); });
  add_sheet(m, 4, 4, [](int r, int c) { return Vec3(-1.5 + c, 1.6 + r, -0.05); });
  const MeshTopology topo = build_mesh_topology(static_cast<int>(m.x.size()), m.tris);
  const auto pairs = self_collision_pairs_brute(m.x, m.tris);
  ASSERT_FALSE(pairs.empty());
  GiaResult g;
  analyse_intersections(m.x, m.tris, topo, pairs, g);
  EXPECT_GT(g.cut_edges, 0);
  EXPECT_EQ(g.unseparated_cut_edges, g.cut_edges);
  EXPECT_TRUE(g.regions.empty());
  EXPECT_EQ(g.component_size, (std::vector<int>{12, 16}));  // one flood per sheet, covering it
  EXPECT_EQ(g.unresolved_pairs, static_cast<int>(pairs.size()));
  for (auto r : g.pair_resolved) EXPECT_EQ(r, 0);
}

// Between the two: B's corner pokes through A's interior. A: 3 x 3 nodes 2 m apart in z = 0
// (ids 0..8). B: 2 x 2 nodes below A (ids 9..12), its corner node (1, 0) = id 11 lifted to
// (2.2, 2.3, 0.5), in B's triangle (9, 12, 11) only. By hand: B's edges 11-12 and 9-11 cross
// z = 0 at (2.25, 2.3) and (1.922, 2.022), inside A: node 11 is cut off, a region on B. On A,
// the crossing segment between those points meets one A edge, (2,2)-(2,4) = ids 4-7, which
// stays connected around it: unseparated, no region on A. The pairs are B's triangle 9 with
// A's triangles (3,4,7) and (4,8,7); both resolve through node 11, pulled toward the centroid
// of those two triangles' vertices, (2, 3, 0): direction (-0.2, 0.7, -0.5)/|.|.
TEST(Gia, CornerThroughSheetIsResolvedFromTheCornerSide) {
  SheetMesh m;
  add_sheet(m, 3, 3, [](int r, int c) { return Vec3(2.0 * c, 2.0 * r, 0); });
  add_sheet(m, 2, 2, [](int r, int c) { return Vec3(1.7 + 0.6 * c, 1.8 + 0.5 * r, -0.4 - 0.1 * c); });
  m.x[11] = Vec3(2.2, 2.3, 0.5);  // B node (1, 0)
  const MeshTopology topo = build_mesh_topology(static_cast<int>(m.x.size()), m.tris);
  const auto pairs = self_collision_pairs_brute(m.x, m.tris);
  ASSERT_FALSE(pairs.empty());
  GiaResult g;
  analyse_intersections(m.x, m.tris, topo, pairs, g);
  EXPECT_EQ(pairs, (std::vector<TrianglePair>{{4, 9}, {7, 9}}));  // A's (3,4,7) = 4, (4,8,7) = 7
  EXPECT_EQ(cut_edge_set(topo, g), (std::set<std::array<int, 2>>{{4, 7}, {9, 11}, {11, 12}}));
  EXPECT_EQ(g.unseparated_cut_edges, 1);
  EXPECT_EQ(region_vertices(g), (std::vector<std::vector<int>>{{11}}));
  EXPECT_EQ(g.unresolved_pairs, 0);
  EXPECT_LT((g.pull[g.component[11]] - Vec3(-0.2, 0.7, -0.5).normalized()).norm(), 1e-12);
}

TEST(Gia, SegmentPiercesTriangleIsClosedAndExact) {
  const Triangle t{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  EXPECT_TRUE(segment_pierces_triangle(Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), t));
  EXPECT_TRUE(segment_pierces_triangle(Vec3(0.5, 0.5, -1), Vec3(0.5, 0.5, 1), t));   // through the hypotenuse
  EXPECT_TRUE(segment_pierces_triangle(Vec3(0, 0, -1), Vec3(0, 0, 0), t));           // ends on a vertex
  EXPECT_FALSE(segment_pierces_triangle(Vec3(0.6, 0.6, -1), Vec3(0.6, 0.6, 1), t));  // beside it
  EXPECT_FALSE(segment_pierces_triangle(Vec3(0.2, 0.2, 0.1), Vec3(0.2, 0.2, 1), t)); // above it
  EXPECT_FALSE(segment_pierces_triangle(Vec3(-1, 0.2, 0), Vec3(2, 0.2, 0), t));      // in its plane
}

}  // namespace
}  // namespace tecido
