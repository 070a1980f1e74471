// Particles against spheres and boxes in the running engine, hand-worked: time of contact and
// rebound of a drop, an oblique hit reflected about the sphere's normal, a moving sphere hitting a
// particle at rest (eq. 9 relative to the surface), the obstacle's elasticity replacing the
// particle's, friction on a box face step by step, resting without sinking, thin boxes at
// steps up to 10 s and a box sweeping through particles: never a step ending inside. Spheres off the
// origin, still or moving, at steps up to 10 s; a particle sliding over a sphere without chattering;
// a spring grid on an off-centre sphere never left inside by rounding.
#include "core/geometry/segment_box.h"
#include "core/geometry/segment_sphere.h"
#include "core/simulation/simulation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido {
namespace {

constexpr double kGravity = 9.81;
constexpr IntegratorKind kAllIntegrators[] = {IntegratorKind::Euler, IntegratorKind::Symplectic, IntegratorKind::Midpoint,
                                   IntegratorKind::RK4};

Obstacle sphere(const Vec3& c, double r) {
  Obstacle o;
  o.kind = ObstacleKind::Sphere;
  o.center = c;
  o.radius = r;
  return o;
}

Obstacle box(const Vec3& c, const Vec3& h) {
  Obstacle o;
  o.kind = ObstacleKind::Box;
  o.center = c;
  o.half_extents = h;
  return o;
}

Scene one_particle(const Vec3& x, const Vec3& v, double k, IntegratorKind integ, double dt, bool gravity) {
  Scene s;
  s.integrator = integ;
  s.dt = dt;
  if (gravity) s.forces.gravity = Vec3(0, 0, -kGravity);
  s.particles.add(x, v, 1.0, k, false);
  return s;
}

TEST(ObstacleContacts, DropOnASphereHitsAtTheRootAndReboundsWithK) {
  // From rest at height d above the top of a sphere, straight over its centre: contact at
  // sqrt(2 d / g), speed sqrt(2 g d), normal +z; rebound k times that speed.
  const double d = 0.8, r = 0.5, k = 0.6, tol = 1e-9;
  for (IntegratorKind integ : {IntegratorKind::Midpoint, IntegratorKind::RK4}) {
    Scene s = one_particle(Vec3(0, 0, 1.0 + r + d), Vec3::Zero(), k, integ, 0.01, true);
    s.contact.bisection_tolerance = tol;
    s.obstacles.push_back(sphere(Vec3(0, 0, 1.0), r));
    Simulation sim(s);
    sim.set_log_contacts(true);
    sim.run(60);
    ASSERT_FALSE(sim.contact_log().empty());
    const ContactEvent& e = sim.contact_log().front();
    EXPECT_EQ(e.obstacle, 0);
    EXPECT_EQ(e.plane, -1);
    EXPECT_NEAR(e.time, std::sqrt(2 * d / kGravity), tol + 1e-12);
    EXPECT_NEAR(e.velocity_before.z(), -std::sqrt(2 * kGravity * d), 1e-6);
    EXPECT_EQ(e.velocity_after.z(), -k * e.velocity_before.z());
    EXPECT_EQ(e.kind, ContactKind::Elastic);
  }
}

TEST(ObstacleContacts, ObliqueHitReflectsAboutTheSphereNormal) {
  // Along z = 1/2 at 1 m/s towards a unit sphere: it is reached at x = -sqrt(3)/2, where the normal
  // is (-sqrt(3)/2, 0, 1/2); with k = 1, v' = v - 2 (v.n) n = (-1/2, 0, sqrt(3)/2).
  Scene s = one_particle(Vec3(-2, 0, 0.5), Vec3(1, 0, 0), 1.0, IntegratorKind::Symplectic, 0.05, false);
  s.contact.bisection_tolerance = 1e-12;
  s.obstacles.push_back(sphere(Vec3::Zero(), 1.0));
  Simulation sim(s);
  sim.set_log_contacts(true);
  sim.run(40);
  ASSERT_EQ(sim.contact_log().size(), 1u);
  const ContactEvent& e = sim.contact_log().front();
  EXPECT_NEAR(e.time, 2.0 - std::sqrt(3.0) / 2.0, 1e-11);
  EXPECT_NEAR(e.velocity_after.x(), -0.5, 1e-9);
  EXPECT_NEAR(e.velocity_after.z(), std::sqrt(3.0) / 2.0, 1e-9);
  EXPECT_NEAR(e.velocity_after.y(), 0.0, 1e-15);
}

TEST(ObstacleContacts, MovingSphereHitsAParticleAtRestRelativeToItsSurface) {
  // A unit sphere at x = 2 moving at -1 m/s reaches a particle at rest at the origin at t = 1.
  // Relative velocity (1, 0, 0), normal (-1, 0, 0): v_rel' = -k (1, 0, 0), v = v_rel' + u = -(1 + k).
  for (const auto& [obstacle_k, expected] : {std::pair<double, double>{-1.0, -2.0}, {0.5, -1.5}}) {
    Scene s = one_particle(Vec3::Zero(), Vec3::Zero(), 1.0, IntegratorKind::Symplectic, 0.03, false);
    Obstacle o = sphere(Vec3(2, 0, 0), 1.0);
    o.velocity = Vec3(-1, 0, 0);
    if (obstacle_k >= 0.0) o.elasticity = obstacle_k;  // replaces the particle's k = 1
    s.obstacles.push_back(o);
    Simulation sim(s);
    sim.set_log_contacts(true);
    for (int n = 0; n < 100; ++n) {
      ASSERT_TRUE(sim.step());
      const Vec3 c = o.center + sim.time() * o.velocity;
      ASSERT_FALSE(inside_sphere(sim.particles().x[0] - c, 1.0)) << "step " << n;
    }
    ASSERT_EQ(sim.contact_log().size(), 1u);
    EXPECT_NEAR(sim.contact_log().front().time, 1.0, 1e-6);
    EXPECT_NEAR(sim.particles().v[0].x(), expected, 1e-12);
  }
}

TEST(ObstacleContacts, FrictionOnABoxFaceHalvesTheSlideEachStep) {
  // On the top face (z = 0) sliding at 1 m/s with mu = 1/2: every step's static contact scales vt by
  // 1/2 while |vt| > 0.01 m/s, then zeroes it: vx = 2^-n for n <= 7, 0 from step 8.
  Scene s = one_particle(Vec3(0, 0, 0), Vec3(1, 0, 0), 0.5, IntegratorKind::Symplectic, 0.001, true);
  Obstacle o = box(Vec3(0, 0, -0.5), Vec3(10, 10, 0.5));
  o.friction = 0.5;
  s.obstacles.push_back(o);
  Simulation sim(s);
  for (int n = 1; n <= 10; ++n) {
    ASSERT_TRUE(sim.step());
    EXPECT_EQ(sim.particles().v[0].x(), n <= 7 ? std::ldexp(1.0, -n) : 0.0) << "step " << n;
    EXPECT_EQ(sim.particles().x[0].z(), 0.0);
  }
  EXPECT_EQ(sim.obstacle_contacts().resting().size(), 1u);
}

TEST(ObstacleContacts, RestsOnABoxWithoutSinkingOrEvents) {
  // Dropped with k = 0 at a small step: the landing is static (|vn| = g dt < 0.01), the particle
  // rests exactly on the face, and no further contact event happens.
  Scene s = one_particle(Vec3(0.2, 0.1, 0.05), Vec3::Zero(), 0.0, IntegratorKind::Symplectic, 0.001, true);
  s.obstacles.push_back(box(Vec3(0, 0, -0.5), Vec3(1, 1, 0.5)));
  Simulation sim(s);
  sim.run(200);
  ASSERT_EQ(sim.obstacle_contacts().resting().size(), 1u);
  const long long events = sim.contacts().events;
  for (int n = 0; n < 5000; ++n) {
    ASSERT_TRUE(sim.step());
    ASSERT_EQ(sim.particles().x[0].z(), 0.0) << "step " << n;
  }
  EXPECT_EQ(sim.contacts().events, events);
  EXPECT_EQ(sim.obstacle_contacts().counters().guard_corrections, 0);
}

TEST(ObstacleContacts, ThinBoxIsNeverTunnelledAtStepsUpTo10s) {
  // 1 km/s at a 2 mm box under gravity, every integrator, steps from 1 ms to 10 s: every step ends
  // on or above the top face.
  const Vec3 h(1, 1, 1e-3);
  for (IntegratorKind integ : kAllIntegrators) {
    for (double dt : {1e-3, 0.1, 1.0, 10.0}) {
      Scene s = one_particle(Vec3(0.3, -0.2, 5), Vec3(0, 0, -1000), 0.5, integ, dt, true);
      s.obstacles.push_back(box(Vec3::Zero(), h));
      Simulation sim(s);
      for (int n = 0; n < 30; ++n) {
        if (!sim.step()) break;  // an explicit integrator may go unstable bouncing; never through
        const Vec3 x = sim.particles().x[0];
        ASSERT_FALSE(inside_box(x, h)) << integrator_name(integ) << " dt " << dt << " step " << n;
        ASSERT_GE(x.z(), h.z()) << integrator_name(integ) << " dt " << dt << " step " << n;
      }
      EXPECT_GT(sim.contacts().events + sim.contacts().cap_hits, 0);
    }
  }
}

TEST(ObstacleContacts, MovingThinBoxPushesParticlesAheadAtAnyStep) {
  // A 2 mm plate rising at 100 m/s through a column of particles at rest (no gravity): after every
  // step each particle is on or above the plate's top face.
  const Vec3 h(1, 1, 1e-3);
  for (double dt : {1e-3, 0.05, 1.0}) {
    Scene s;
    s.dt = dt;
    for (int k = 0; k < 5; ++k) s.particles.add(Vec3(0.1 * k, 0, 0.5 + k), Vec3::Zero(), 1.0, 0.5, false);
    Obstacle o = box(Vec3::Zero(), h);
    o.velocity = Vec3(0, 0, 100);
    s.obstacles.push_back(o);
    Simulation sim(s);
    // Until the plate has passed the highest particle's start (z = 4.5 m at t = 0.045 s).
    for (int n = 0; n < 20 || sim.time() < 0.1; ++n) {
      ASSERT_TRUE(sim.step());
      const double top = sim.time() * 100.0 + h.z();
      for (std::size_t i = 0; i < 5; ++i) ASSERT_GE(sim.particles().x[i].z(), top) << "dt " << dt << " step " << n;
    }
    // Every particle was hit and now moves at least as fast as the plate.
    for (std::size_t i = 0; i < 5; ++i) EXPECT_GE(sim.particles().v[i].z(), 100.0 - 1e-9);
  }
}

TEST(ObstacleContacts, RotatingBarPushesAParticleAtTheAngleItReachesIt) {
  // A bar (half extents 1, 0.05, 0.5) turning about z at 1 rad/s from along x; a particle at rest at
  // (0, 0.8, 0). In the bar's frame the particle sits at (0.8 sin t, 0.8 cos t): the +y face
  // (y = 0.05) reaches it at t = acos(0.05 / 0.8).
  Scene s = one_particle(Vec3(0, 0.8, 0), Vec3::Zero(), 0.5, IntegratorKind::Symplectic, 1e-3, false);
  s.contact.bisection_tolerance = 1e-10;
  Obstacle o = box(Vec3::Zero(), Vec3(1, 0.05, 0.5));
  o.angular_velocity = Vec3(0, 0, 1);
  s.obstacles.push_back(o);
  Simulation sim(s);
  sim.set_log_contacts(true);
  ObstaclePose pose;
  for (int n = 0; n < 2000; ++n) {
    ASSERT_TRUE(sim.step());
    obstacle_pose_at(o, sim.time(), pose);
    ASSERT_FALSE(inside_box(pose.to_local(sim.particles().x[0]), o.half_extents)) << "step " << n;
  }
  ASSERT_FALSE(sim.contact_log().empty());
  EXPECT_NEAR(sim.contact_log().front().time, std::acos(0.05 / 0.8), 1e-6);
  EXPECT_EQ(sim.contact_log().front().feature, 3);  // +y
}

TEST(ObstacleContacts, OffCentreSphereStillOrMovingIsNeverEndedInsideAtStepsUpTo10s) {
  // A sphere whose centre is not a round number (centre + offset rounds: a placement must be
  // nudged out after adding it), still or moving across the particle's path, a particle at
  // 1 km/s under gravity, every integrator, steps from 1 ms to 10 s: no step ends inside.
  const Vec3 c(0.3, 0.7, -0.1);
  for (const Vec3& vel : {Vec3(0, 0, 0), Vec3(0.7, -0.3, 0.9)}) {
    for (IntegratorKind integ : kAllIntegrators) {
      for (double dt : {1e-3, 0.1, 1.0, 10.0}) {
        Scene s = one_particle(c + Vec3(0.01, 0.02, 3), Vec3(0, 0, -1000), 0.3, integ, dt, true);
        Obstacle o = sphere(c, 0.3);
        o.velocity = vel;
        s.obstacles.push_back(o);
        Simulation sim(s);
        ObstaclePose pose;
        for (int n = 0; n < 30; ++n) {
          if (!sim.step()) break;  // an explicit integrator may go unstable bouncing; never through
          obstacle_pose_at(o, sim.time(), pose);
          ASSERT_FALSE(inside_sphere(sim.particles().x[0] - pose.center, o.radius))
              << integrator_name(integ) << " dt " << dt << " step " << n;
        }
        EXPECT_GT(sim.contacts().events + sim.contacts().cap_hits, 0);
      }
    }
  }
}

TEST(ObstacleContacts, RestsOnAnOffCentreSphereTopWithoutEvents) {
  // Dropped 1 cm onto the top of an off-centre sphere, k = 0: one contact, then it rests there for
  // 10^4 steps, on the sphere, with no further contact event (a placement left inside by rounding
  // would be found again every step).
  const Vec3 c(0.3, 0.7, -0.1);
  Scene s = one_particle(c + Vec3(0, 0, 0.31), Vec3::Zero(), 0.0, IntegratorKind::Symplectic, 0.01, true);
  s.obstacles.push_back(sphere(c, 0.3));
  Simulation sim(s);
  for (int n = 0; n < 10000; ++n) {
    ASSERT_TRUE(sim.step());
    ASSERT_FALSE(inside_sphere(sim.particles().x[0] - c, 0.3)) << "step " << n;
  }
  EXPECT_LE(sim.contacts().events, 2);
  EXPECT_NEAR((sim.particles().x[0] - c).norm(), 0.3, 1e-12);
  EXPECT_NEAR(sim.particles().x[0].x(), c.x(), 1e-12);
  EXPECT_EQ(sim.obstacle_contacts().counters().guard_corrections, 0);
}

TEST(ObstacleContacts, SlidesOverASphereWithoutChattering) {
  // Dropped 1 cm onto a sphere 0.1 m off its top, k = 0.2: after a few bounces it rests and slides
  // down the curve (each step along the tangent ends (v h)^2 / 2r above it: no reason to let go)
  // until the curve can no longer hold it, then falls free. A handful of contacts in all, not one
  // per step.
  const Vec3 c(0, 0, 0);
  Scene s = one_particle(Vec3(0.1, 0, std::sqrt(0.09 - 0.01) + 0.01), Vec3::Zero(), 0.2, IntegratorKind::Symplectic,
                         0.002, true);
  s.obstacles.push_back(sphere(c, 0.3));
  Simulation sim(s);
  for (int n = 0; n < 1500; ++n) {
    ASSERT_TRUE(sim.step());
    ASSERT_FALSE(inside_sphere(sim.particles().x[0] - c, 0.3)) << "step " << n;
  }
  EXPECT_LE(sim.contacts().events, 10);
  EXPECT_LT(sim.particles().x[0].z(), -1.0);  // it left the sphere and fell
}

TEST(ObstacleContacts, SpringGridOnAnOffCentreSphereNeverEndsAStepInside) {
  // A 7 x 7 grid of particles and springs dropped on an off-centre sphere: placements on the sphere
  // must stay outside after the centre is added (centre + offset rounds), or the next interval
  // starts inside. No particle inside after any step, and no end-of-step guard needed.
  const Vec3 c(0.3, 0.7, -0.1);
  Scene s;
  s.dt = 0.002;
  s.forces.gravity = Vec3(0, 0, -kGravity);
  s.forces.air_drag = 0.001;
  const int n = 7;
  const double d = 0.6 / (n - 1);
  for (int r = 0; r < n; ++r)
    for (int q = 0; q < n; ++q)
      s.particles.add(c + Vec3(-0.3 + d * q, -0.3 + d * r, 0.4), Vec3::Zero(), 0.01, 0.2, false);
  for (int r = 0; r < n; ++r)
    for (int q = 0; q < n; ++q) {
      if (q + 1 < n) s.forces.springs.push_back(Spring{r * n + q, r * n + q + 1, 20.0, d, 0.0});
      if (r + 1 < n) s.forces.springs.push_back(Spring{r * n + q, (r + 1) * n + q, 20.0, d, 0.0});
    }
  Obstacle o = sphere(c, 0.3);
  o.friction = 0.5;
  s.obstacles.push_back(o);
  Simulation sim(s);
  for (int k = 0; k < 1000; ++k) {
    ASSERT_TRUE(sim.step());
    for (int i = 0; i < n * n; ++i)
      ASSERT_FALSE(inside_sphere(sim.particles().x[i] - c, 0.3)) << "particle " << i << " step " << k;
  }
  EXPECT_GT(sim.obstacle_contacts().counters().contacts, 0);
  EXPECT_EQ(sim.obstacle_contacts().counters().guard_corrections, 0);
}

TEST(ObstacleContacts, PlanesAloneStepAsBefore) {
  // A scene without obstacles takes the plane-only path: an empty obstacle list changes nothing.
  Scene s = one_particle(Vec3(0, 0, 1), Vec3(1, 0, 2), 0.5, IntegratorKind::Symplectic, 0.013, true);
  s.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(10, 10), 0.3));
  Scene with = s;
  with.obstacles.push_back(sphere(Vec3(100, 100, 100), 1.0));  // far away: never touched
  Simulation a(s), b(with);
  a.run(300);
  b.run(300);
  EXPECT_EQ(a.particles().x[0], b.particles().x[0]);
  EXPECT_EQ(a.particles().v[0], b.particles().v[0]);
  EXPECT_EQ(a.contacts().events, b.contacts().events);
}

}  // namespace
}  // namespace tecido
