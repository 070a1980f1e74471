// Particles against triangle-mesh obstacles in the running engine, hand-worked: a drop on one
// triangle (time and rebound), two-sided triangles and a particle that goes round one before it
// comes back through it, a closed box mesh against the analytic box, a keyframed triangle rising
// through a particle at rest, and sliding across the diagonal of a box mesh's top face.
#include "core/geometry/box_mesh.h"
#include "core/geometry/orient_predicates.h"
#include "core/simulation/simulation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido {
namespace {

constexpr double kG = 9.81;

Obstacle triangle_mesh(const std::vector<Vec3>& v) {
  Obstacle o;
  o.kind = ObstacleKind::Mesh;
  o.vertices = v;
  o.triangles = {{0, 1, 2}};
  o.center = (v[0] + v[1] + v[2]) / 3.0;
  return o;
}

/// The triangle (-2,-2,z) (2,-2,z) (0,2,z), normal +z; at y = 0 it spans x in [-1, 1].
Obstacle floor_triangle(double z = 0.0) { return triangle_mesh({Vec3(-2, -2, z), Vec3(2, -2, z), Vec3(0, 2, z)}); }

Obstacle box_as_mesh(const Vec3& c, const Vec3& h) {
  Obstacle o;
  o.kind = ObstacleKind::Mesh;
  for (const Vec3& q : box_corners(h)) o.vertices.push_back(c + q);
  o.triangles.assign(kBoxTriangles.begin(), kBoxTriangles.end());
  o.center = c;
  return o;
}

Scene one_particle(const Vec3& x, const Vec3& v, double k, IntegratorKind integ, double dt) {
  Scene s;
  s.integrator = integ;
  s.dt = dt;
  s.contact.bisection_tolerance = 1e-10;
  s.particles.add(x, v, 1.0, k, false);
  return s;
}

TEST(MeshObstacleContacts, DropOnATriangleHitsAtTheRootAndRebounds) {
  for (IntegratorKind integ : {IntegratorKind::Midpoint, IntegratorKind::RK4}) {
    Scene s = one_particle(Vec3(0.1, 0.2, 1.0), Vec3::Zero(), 0.7, integ, 0.01);
    s.forces.gravity = Vec3(0, 0, -kG);
    s.obstacles.push_back(floor_triangle());
    Simulation sim(s);
    sim.set_log_contacts(true);
    sim.run(60);
    ASSERT_FALSE(sim.contact_log().empty());
    const ContactEvent& e = sim.contact_log().front();
    EXPECT_EQ(e.obstacle, 0);
    EXPECT_EQ(e.feature, 0);
    EXPECT_NEAR(e.time, std::sqrt(2.0 / kG), 1e-9);
    EXPECT_NEAR(e.velocity_after.z(), -0.7 * e.velocity_before.z(), 1e-12);
  }
}

TEST(MeshObstacleContacts, GoesRoundATriangleThenHitsItFromBelow) {
  // Gravity +2 m/s^2 (up), z = 1 - 3 t + t^2, x = 5 - 2 t, y = 0: z = 0 at t = (3 - sqrt 5)/2
  // (x = 4.24, beside the triangle: no contact, the side flips) and at t = (3 + sqrt 5)/2
  // (x = -0.236, inside it, from below): contact with vz = sqrt 5; k = 1 sends it back down.
  for (IntegratorKind integ : {IntegratorKind::Midpoint, IntegratorKind::RK4}) {
    Scene s = one_particle(Vec3(5, 0, 1), Vec3(-2, 0, -3), 1.0, integ, 0.01);
    s.forces.gravity = Vec3(0, 0, 2);
    s.obstacles.push_back(floor_triangle());
    Simulation sim(s);
    sim.set_log_contacts(true);
    sim.run(300);
    ASSERT_EQ(sim.contact_log().size(), 1u) << integrator_name(integ);
    const ContactEvent& e = sim.contact_log().front();
    EXPECT_NEAR(e.time, (3.0 + std::sqrt(5.0)) / 2.0, 1e-9);
    EXPECT_NEAR(e.velocity_before.z(), std::sqrt(5.0), 1e-9);
    EXPECT_NEAR(e.velocity_after.z(), -std::sqrt(5.0), 1e-9);
    EXPECT_LT(sim.particles().x[0].z(), 0.0);  // still below: it never passed through
  }
}

TEST(MeshObstacleContacts, ClosedBoxMeshMatchesTheAnalyticBox) {
  const Vec3 c(0.3, -0.1, 0.0), h(0.5, 0.4, 0.2);
  double times[2], speeds[2];
  for (int kind = 0; kind < 2; ++kind) {
    Scene s = one_particle(Vec3(0.4, 0.0, 1.0), Vec3(0.1, 0, 0), 0.5, IntegratorKind::RK4, 0.01);
    s.forces.gravity = Vec3(0, 0, -kG);
    if (kind == 0) {
      Obstacle b;
      b.kind = ObstacleKind::Box;
      b.center = c;
      b.half_extents = h;
      s.obstacles.push_back(b);
    } else {
      s.obstacles.push_back(box_as_mesh(c, h));
    }
    Simulation sim(s);
    sim.set_log_contacts(true);
    sim.run(60);
    ASSERT_FALSE(sim.contact_log().empty());
    times[kind] = sim.contact_log().front().time;
    speeds[kind] = sim.contact_log().front().velocity_after.z();
  }
  // Dropped 0.8 m onto the top face z = 0.2.
  EXPECT_NEAR(times[0], std::sqrt(2 * 0.8 / kG), 1e-9);
  EXPECT_NEAR(times[1], times[0], 1e-9);
  EXPECT_NEAR(speeds[1], speeds[0], 1e-8);
}

TEST(MeshObstacleContacts, KeyframedTriangleRisingPushesAParticleAtRest) {
  // The triangle rises from z = 0 at t = 0 to z = 1 at t = 1, then holds; a particle at rest at
  // z = 0.5 is reached at t = 0.5 with relative velocity -1: with k = 1 it leaves at 1 + 1 = 2 m/s.
  Scene s = one_particle(Vec3(0, 0, 0.5), Vec3::Zero(), 1.0, IntegratorKind::Symplectic, 0.03);
  Obstacle o = floor_triangle();
  o.frames = {{0.0, o.vertices}, {1.0, floor_triangle(1.0).vertices}};
  s.obstacles.push_back(o);
  Simulation sim(s);
  sim.set_log_contacts(true);
  ObstaclePose pose;
  for (int n = 0; n < 60; ++n) {
    ASSERT_TRUE(sim.step());
    obstacle_pose_at(o, sim.time(), pose);
    ASSERT_GE(sim.particles().x[0].z(), pose.vertices[0].z()) << "step " << n;
  }
  ASSERT_EQ(sim.contact_log().size(), 1u);
  EXPECT_NEAR(sim.contact_log().front().time, 0.5, 1e-9);
  EXPECT_NEAR(sim.particles().v[0].z(), 2.0, 1e-12);
}

TEST(MeshObstacleContacts, SlidesAcrossTheDiagonalOfABoxMeshTopFace) {
  // Landing softly on the top face (z = 0) of a box mesh, then sliding frictionless across the
  // diagonal shared by its two top triangles: it never leaves the face, never goes below it, and
  // keeps its horizontal velocity.
  const Vec3 h(1, 1, 0.5);
  Scene s = one_particle(Vec3(-0.6, 0.5, 0.0), Vec3(0.8, -0.6, 0), 0.0, IntegratorKind::Symplectic, 0.001);
  s.forces.gravity = Vec3(0, 0, -kG);
  s.obstacles.push_back(box_as_mesh(Vec3(0, 0, -0.5), h));
  Simulation sim(s);
  for (int n = 0; n < 1500; ++n) {
    ASSERT_TRUE(sim.step());
    ASSERT_EQ(sim.particles().x[0].z(), 0.0) << "step " << n;
  }
  EXPECT_NEAR(sim.particles().x[0].x(), -0.6 + 0.8 * sim.time(), 1e-9);
  EXPECT_NEAR(sim.particles().v[0].y(), -0.6, 1e-12);
}

}  // namespace
}  // namespace tecido
