// The seed's edge modes (section 3.1.3, fig. 20; edge_response.h) on a hand-built 5 x 5 grid:
// p- and p+ from the border distances, the three push directions, and the velocity change
// strength * dt / m applied once per particle, never to a pinned one.
#include "core/cloth/edge_response.h"
#include "core/cloth/mesh_topology.h"
#include "core/scene/cloth_builder.h"

#include <gtest/gtest.h>

namespace tecido {
namespace {

// 5 x 5 nodes, node (r, c) at (c, r, 0), id 5r + c. Border distances:
//   0 0 0 0 0
//   0 1 1 1 0
//   0 1 2 1 0
//   ...
// Neighbours of (r, c): (r, c-1), (r, c+1), (r-1, c), (r+1, c), (r-1, c-1), (r+1, c+1).
struct Grid {
  Scene scene;
  MeshTopology topo;
  Grid() {
    ClothGridSpec spec;
    spec.rows = spec.cols = 5;
    spec.spacing = 1.0;
    spec.total_mass = 25.0;
    spec.stiffness_b = 1.0;
    append_cloth(scene, spec);
    topo = build_mesh_topology(25, scene.triangles);
  }
};

// Node P = (1, 2), id 7, distance 1, lifted to z = 0.3. Its neighbours: (1,1) d1, (1,3) d1,
// (0,2) d0, (2,2) d2, (0,1) d0, (2,3) d1. So p- = mean of (0,2), (0,1) = (1.5, 0, 0) and
// p+ = (2,2) = (2, 2, 0). With P = (2, 1, 0.3):
//   mode 1: P - p-             = (0.5, 1, 0.3)
//   mode 2: p+ - P             = (0, 1, -0.3)
//   mode 3: (p+ + p-)/2 - P    = (1.75, 1, 0) - P = (-0.25, 0, -0.3)
TEST(EdgeResponse, InteriorParticleDirectionsByHand) {
  Grid g;
  std::vector<Vec3> x = g.scene.particles.x;
  x[7].z() = 0.3;
  const BorderNeighbours b = border_neighbours(g.topo, x, 7);
  EXPECT_LT((b.nearer - Vec3(1.5, 0, 0)).norm(), 1e-15);
  EXPECT_LT((b.farther - Vec3(2, 2, 0)).norm(), 1e-15);
  EXPECT_LT((edge_mode_direction(EdgeMode::AwayFromNearer, g.topo, x, 7) - Vec3(0.5, 1, 0.3).normalized()).norm(), 1e-15);
  EXPECT_LT((edge_mode_direction(EdgeMode::TowardFarther, g.topo, x, 7) - Vec3(0, 1, -0.3).normalized()).norm(), 1e-15);
  EXPECT_LT((edge_mode_direction(EdgeMode::TowardMidpoint, g.topo, x, 7) - Vec3(-0.25, 0, -0.3).normalized()).norm(), 1e-15);
}

// Node Q = (0, 2), id 2, on the border: neighbours (0,1) d0, (0,3) d0, (1,2) d1, (1,3) d1.
// p- = mean of (0,1), (0,3) = (2, 0, 0) = Q at rest: mode 1 has no direction (flat border);
// p+ = mean of (1,2), (1,3) = (2.5, 1, 0): mode 2 -> (0.5, 1, 0); mode 3 -> (2.25, 0.5) - Q =
// (0.25, 0.5, 0). Bend the border (lift (0,1) by 0.4): p- = (2, 0, 0.2), mode 1 -> (0, 0, -0.2).
TEST(EdgeResponse, BorderParticleDirectionsByHand) {
  Grid g;
  std::vector<Vec3> x = g.scene.particles.x;
  EXPECT_EQ(edge_mode_direction(EdgeMode::AwayFromNearer, g.topo, x, 2), Vec3::Zero());
  EXPECT_LT((edge_mode_direction(EdgeMode::TowardFarther, g.topo, x, 2) - Vec3(0.5, 1, 0).normalized()).norm(), 1e-15);
  EXPECT_LT((edge_mode_direction(EdgeMode::TowardMidpoint, g.topo, x, 2) - Vec3(0.25, 0.5, 0).normalized()).norm(), 1e-15);
  // At rest an interior particle's mode 3 target is itself: no push.
  EXPECT_EQ(edge_mode_direction(EdgeMode::TowardMidpoint, g.topo, x, 12), Vec3::Zero());
  x[1].z() = 0.4;
  EXPECT_LT((edge_mode_direction(EdgeMode::AwayFromNearer, g.topo, x, 2) - Vec3(0, 0, -1)).norm(), 1e-15);
}

// The response on "contact" pairs: triangles 12 = (7, 8, 13) [quad (1, 2), first half] and
// 0 = (0, 1, 6). Particles 0, 1, 6, 7, 8, 13 are each pushed once, by strength * dt / m along
// their mode direction; particle 0 is pinned and is not; nothing else moves.
TEST(EdgeResponse, VelocityChangeOncePerParticleAndNoneForPinned) {
  Grid g;
  std::vector<Vec3> x = g.scene.particles.x;
  x[7].z() = 0.3;
  x[13].z() = -0.2;
  x[6].y() += 0.1;
  std::vector<double> inv_mass = g.scene.particles.inv_mass;
  inv_mass[0] = 0.0;
  ASSERT_EQ(g.scene.triangles[12], (std::array<int, 3>{7, 8, 13}));
  ASSERT_EQ(g.scene.triangles[0], (std::array<int, 3>{0, 1, 6}));
  // Triangle 12 listed twice (in two pairs): still one push per particle.
  const std::vector<TrianglePair> pairs = {{0, 12}, {12, 20}};
  const std::uint8_t skip[2] = {0, 1};  // the second pair is skipped (e.g. resolved by GIA)
  std::vector<Vec3> v(25, Vec3::Zero());
  std::vector<std::uint8_t> mark;
  const double strength = 0.05, dt = 0.01;
  const int pushed = apply_edge_mode(EdgeMode::TowardMidpoint, g.topo, g.scene.triangles, pairs, skip, x, inv_mass,
                                     strength, dt, v, mark);
  int expected_pushed = 0;
  for (int i = 0; i < 25; ++i) {
    const bool in_contact = i == 1 || i == 6 || i == 7 || i == 8 || i == 13;  // 0 is pinned
    const Vec3 d = edge_mode_direction(EdgeMode::TowardMidpoint, g.topo, x, i);
    const Vec3 expected = in_contact ? Vec3(strength * dt * inv_mass[i] * d) : Vec3::Zero();
    EXPECT_EQ(v[i], expected) << i;
    expected_pushed += in_contact && d != Vec3::Zero();
  }
  EXPECT_EQ(pushed, expected_pushed);
  EXPECT_GE(pushed, 4);
  // Triangle 20 (second pair, skipped) moved nobody outside triangles 0 and 12.
  for (int i : g.scene.triangles[20]) {
    if (i != 7 && i != 8 && i != 13) {
      EXPECT_EQ(v[i], Vec3::Zero()) << i;
    }
  }
}

}  // namespace
}  // namespace tecido
