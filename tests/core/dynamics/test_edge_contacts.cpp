// Springs against obstacle edges, hand-worked. A spring sliding diagonally at a box's vertical
// edge (no particle touches a face) meets it at its middle at a known time and comes back with k
// times its approach speed along the edge's normal; without edge contacts the same spring cuts
// through the corner. The same with the box moving and the spring at rest, with the box given as
// a mesh, and a spring bridging two top edges under gravity coming to rest without cutting in or
// gaining energy.
#include "core/geometry/box_mesh.h"
#include "core/geometry/segment_box.h"
#include "core/simulation/simulation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido {
namespace {

const Vec3 kHalf(0.25, 0.25, 0.25);

Obstacle unit_box(bool as_mesh) {
  Obstacle o;
  o.center = Vec3::Zero();
  if (!as_mesh) {
    o.kind = ObstacleKind::Box;
    o.half_extents = kHalf;
    return o;
  }
  o.kind = ObstacleKind::Mesh;
  for (const Vec3& q : box_corners(kHalf)) o.vertices.push_back(q);
  o.triangles.assign(kBoxTriangles.begin(), kBoxTriangles.end());
  return o;
}

/// The spring (0, 0.6, 0) - (0.6, 0, 0), both ends outside the box's footprint: its line x + y = 0.6
/// passes the vertical edge at (0.25, 0.25) 0.1 / sqrt 2 away.
Scene diagonal_spring(const Vec3& v, double k, bool edges) {
  Scene s;
  s.dt = 0.01;
  s.contact.bisection_tolerance = 1e-12;
  s.particles.add(Vec3(0, 0.6, 0), v, 1.0, k, false);
  s.particles.add(Vec3(0.6, 0, 0), v, 1.0, k, false);
  s.forces.springs.push_back(Spring{0, 1, 100.0, std::sqrt(0.72), 0.0});
  s.edge_contacts = edges;
  return s;
}

bool cuts_box(const Simulation& sim, const Vec3& center) {
  const auto& x = sim.particles().x;
  return segment_box_depth(x[0] - center, x[1] - center, kHalf) > 0.0;
}

TEST(EdgeContacts, SpringMeetsAVerticalEdgeAtItsMiddleAndBouncesWithK) {
  // Velocity (-u, -u, 0): x + y = 0.6 - 2 u t reaches the edge at x + y = 0.5 at t = 0.05 / u,
  // at the spring's middle (a = 1/2), normal n = (1, 1, 0)/sqrt 2, approach speed v = u sqrt 2.
  // Equal masses: each end gets dv = (1 + k) v n, so both leave at k v n.
  const double u = 1.0 / std::sqrt(2.0), k = 0.4, tc = 0.05 / u;
  const Vec3 n = Vec3(1, 1, 0) / std::sqrt(2.0);
  for (bool mesh : {false, true}) {
    Scene s = diagonal_spring(Vec3(-u, -u, 0), k, true);
    s.obstacles.push_back(unit_box(mesh));
    Simulation sim(s);
    for (int step = 0; step < 30; ++step) {
      ASSERT_TRUE(sim.step());
      ASSERT_FALSE(cuts_box(sim, Vec3::Zero())) << "mesh " << mesh << " step " << step;
    }
    // A box's springs are handled by spring_box_contacts.h, a mesh's by edge_contacts.h.
    const long long contacts =
        mesh ? sim.edge_contacts().counters().contacts : sim.spring_box_contacts().counters().contacts;
    EXPECT_EQ(contacts, 1) << "mesh " << mesh;
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR((sim.particles().v[i] - k * n).norm(), 0.0, 1e-9) << "mesh " << mesh;
      // Where it is now tells when it turned: x(t) = x(tc) + k n (t - tc), x(tc) = x0 - (u, u, 0) tc.
      const Vec3 x0 = i == 0 ? Vec3(0, 0.6, 0) : Vec3(0.6, 0, 0);
      const Vec3 expected = x0 - Vec3(u, u, 0) * tc + k * n * (sim.time() - tc);
      EXPECT_NEAR((sim.particles().x[i] - expected).norm(), 0.0, 1e-8) << "mesh " << mesh;
    }
  }
}

TEST(EdgeContacts, WithoutEdgeContactsTheSpringCutsTheCorner) {
  const double u = 1.0 / std::sqrt(2.0);
  Scene s = diagonal_spring(Vec3(-u, -u, 0), 0.4, false);
  s.obstacles.push_back(unit_box(false));
  Simulation sim(s);
  bool cut = false;
  for (int step = 0; step < 30; ++step) {
    ASSERT_TRUE(sim.step());
    cut = cut || cuts_box(sim, Vec3::Zero());
  }
  EXPECT_TRUE(cut);
  EXPECT_EQ(sim.obstacle_contacts().counters().contacts, 0);  // no particle ever touched the box
}

TEST(EdgeContacts, MovingBoxKicksASpringAtRest) {
  // The box moves at (u, u, 0) into the spring at rest: relative motion as above, so the spring
  // leaves at (1 + k) v n (v = u sqrt 2 = 1), and the box (kinematic) goes on.
  const double u = 1.0 / std::sqrt(2.0), k = 0.4;
  const Vec3 n = Vec3(1, 1, 0) / std::sqrt(2.0);
  Scene s = diagonal_spring(Vec3::Zero(), k, true);
  Obstacle box = unit_box(false);
  box.velocity = Vec3(u, u, 0);
  s.obstacles.push_back(box);
  Simulation sim(s);
  for (int step = 0; step < 30; ++step) {
    ASSERT_TRUE(sim.step());
    ASSERT_FALSE(cuts_box(sim, box.velocity * sim.time())) << "step " << step;
  }
  for (int i = 0; i < 2; ++i) EXPECT_NEAR((sim.particles().v[i] - (1 + k) * n).norm(), 0.0, 1e-9);
}

TEST(EdgeContacts, SpringBridgingTwoEdgesComesToRestWithoutCuttingIn) {
  // A 0.8 m spring dropped 0.1 m onto the 0.5 m wide top of the box, across two parallel top
  // edges, ends hanging free: it lands on the edges and stays on them. The energy never grows
  // beyond its start by more than symplectic Euler's own bounded wobble (omega h = 0.07 here;
  // a contact that pumped energy, as an early version did, multiplied it several times).
  Scene s;
  s.dt = 0.001;
  s.forces.gravity = Vec3(0, 0, -9.81);
  s.forces.air_drag = 0.02;  // 2 s time constant: it settles
  s.particles.add(Vec3(-0.4, 0.05, 0.35), Vec3::Zero(), 0.01, 0.0, false);
  s.particles.add(Vec3(0.4, 0.05, 0.35), Vec3::Zero(), 0.01, 0.0, false);
  s.forces.springs.push_back(Spring{0, 1, 50.0, 0.8, 0.0});
  s.obstacles.push_back(unit_box(false));
  s.edge_contacts = true;
  Simulation sim(s);
  auto energy = [&] {
    const auto& p = sim.particles();
    double e = spring_potential_energy(s.forces.springs, p.x);
    for (int i = 0; i < 2; ++i) e += 0.01 * (0.5 * p.v[i].squaredNorm() + 9.81 * p.x[i].z());
    return e;
  };
  const double e0 = energy();
  for (int step = 0; step < 20000; ++step) {
    ASSERT_TRUE(sim.step());
    ASSERT_FALSE(cuts_box(sim, Vec3::Zero())) << "step " << step;
    ASSERT_LE(energy(), e0 * (1 + 1e-3)) << "step " << step;
  }
  // At rest across the two edges, straight and level: its middle on the top face's height.
  const Vec3 mid = 0.5 * (sim.particles().x[0] + sim.particles().x[1]);
  EXPECT_NEAR(mid.z(), 0.25, 1e-6);
  EXPECT_LT(sim.particles().v[0].norm() + sim.particles().v[1].norm(), 1e-3);
}

}  // namespace
}  // namespace tecido
