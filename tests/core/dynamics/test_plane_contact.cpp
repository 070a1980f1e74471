// Plane contact in the running engine: bisection time of contact vs the analytic root,
// no tunnelling at any step, restitution (elastic branch), friction to rest (static branch),
// the corner of two planes, and the event cap being reported.
#include "core/simulation/simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tecido {
namespace {

Scene ballistic(IntegratorKind k, double h, double tol, double elasticity) {
  Scene s;
  s.integrator = k;
  s.dt = h;
  s.contact.bisection_tolerance = tol;
  s.forces.gravity = Vec3(0, 0, -9.81);
  s.particles.add(Vec3(0, 0, 1.0), Vec3(1.0, 0.0, 2.0), 1.0, elasticity, false);
  s.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(10, 10), 0.0));
  return s;
}

// Root of z(t) = 1 + 2 t - g t^2 / 2.
double analytic_contact_time() {
  const double g = 9.81;
  return (2.0 + std::sqrt(4.0 + 2.0 * g)) / g;
}

TEST(PlaneContact, BisectionTimeOfContactMatchesTheQuadraticRoot) {
  // Midpoint and RK4 integrate constant acceleration exactly, so the sub-step positions are
  // the parabola's and the bisected time must bracket the analytic root within the tolerance.
  for (IntegratorKind k : {IntegratorKind::Midpoint, IntegratorKind::RK4}) {
    for (double h : {0.1, 0.013, 0.001}) {
      for (double tol : {1e-3, 1e-6, 1e-9}) {
        Simulation sim(ballistic(k, h, tol, 0.5));
        sim.set_log_contacts(true);
        sim.run(static_cast<long long>(std::ceil(0.7 / h)));
        ASSERT_FALSE(sim.contact_log().empty()) << integrator_name(k) << " h=" << h;
        const ContactEvent& e = sim.contact_log().front();
        EXPECT_NEAR(e.time, analytic_contact_time(), tol + 1e-12) << integrator_name(k) << " h=" << h << " tol=" << tol;
        EXPECT_EQ(e.kind, ContactKind::Elastic);
      }
    }
  }
}

TEST(PlaneContact, SymplecticEulerContactTimeIsTheRootOfItsOwnSubStep) {
  // A symplectic sub-step of length tau from (z0, vz0) gives z = z0 + tau vz0 - g tau^2: the
  // bisection finds that polynomial's root (in the step where the crossing happens).
  const double h = 0.05, tol = 1e-10, g = 9.81;
  Simulation sim(ballistic(IntegratorKind::Symplectic, h, tol, 0.5));
  sim.set_log_contacts(true);
  double z0 = 0, vz0 = 0, t0 = 0;
  while (sim.contact_log().empty()) {
    z0 = sim.particles().x[0].z();
    vz0 = sim.particles().v[0].z();
    t0 = sim.time();
    sim.step();
  }
  const double tau = (vz0 + std::sqrt(vz0 * vz0 + 4.0 * g * z0)) / (2.0 * g);
  EXPECT_NEAR(sim.contact_log().front().time, t0 + tau, tol + 1e-12);
}

TEST(PlaneContact, RestitutionScalesTheReboundSpeed) {
  for (double k : {0.3, 0.8, 1.0}) {
    Simulation sim(ballistic(IntegratorKind::RK4, 0.01, 1e-9, k));
    sim.set_log_contacts(true);
    sim.run(80);
    ASSERT_FALSE(sim.contact_log().empty());
    const ContactEvent& e = sim.contact_log().front();
    // Impact speed from energy: vz = -sqrt(vz0^2 + 2 g z0); the bounce mirrors vn scaled by k.
    const double vz_impact = -std::sqrt(4.0 + 2.0 * 9.81);
    EXPECT_NEAR(e.velocity_before.z(), vz_impact, 1e-6);
    EXPECT_NEAR(e.velocity_after.z(), -k * e.velocity_before.z(), 1e-12);
    EXPECT_DOUBLE_EQ(e.velocity_after.x(), e.velocity_before.x());  // frictionless: vt kept
  }
}

TEST(PlaneContact, BouncesDecayThenRestOnThePlane) {
  Scene s = ballistic(IntegratorKind::Symplectic, 0.005, 0.0, 0.6);
  s.particles.v[0] = Vec3::Zero();
  Simulation sim(s);
  sim.set_log_contacts(true);
  sim.run(2000);  // 10 s
  ASSERT_GT(sim.contact_log().size(), 5u);
  EXPECT_EQ(sim.resting_contacts().size(), 1u);
  EXPECT_GE(sim.particles().x[0].z(), 0.0);
  EXPECT_LT(sim.particles().x[0].z(), 1e-12);
  EXPECT_LT(sim.particles().v[0].norm(), 1e-12);
  // Successive rebound speeds fall by k (elastic branch) until the static threshold.
  const auto& log = sim.contact_log();
  for (std::size_t i = 0; i + 1 < log.size() && log[i + 1].kind == ContactKind::Elastic; ++i) {
    EXPECT_NEAR(log[i].velocity_after.z(), -0.6 * log[i].velocity_before.z(), 1e-12);
  }
}

TEST(PlaneContact, FrictionBringsASlidingParticleToRest) {
  Scene s;
  s.dt = 0.01;
  s.forces.gravity = Vec3(0, 0, -9.81);
  s.particles.add(Vec3(0, 0, 0), Vec3(2.0, 0.0, 0.0), 1.0, 0.5, false);
  s.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(10, 10), 0.05));
  Simulation sim(s);
  sim.run(300);
  EXPECT_EQ(sim.particles().v[0], Vec3::Zero());
  EXPECT_GE(sim.particles().x[0].z(), 0.0);
  EXPECT_LT(sim.particles().x[0].z(), 1e-12);
  // Each static step scales vt by (1 - mu) until |vt| <= 0.01: sum of the geometric series of
  // displacements bounds the slide.
  const double bound = 2.0 * 0.01 / 0.05 + 0.02;
  EXPECT_GT(sim.particles().x[0].x(), 0.2);
  EXPECT_LT(sim.particles().x[0].x(), bound);
  // Without friction it keeps sliding at 2 m/s.
  s.planes[0].friction = 0.0;
  Simulation free(s);
  free.run(100);
  EXPECT_NEAR(free.particles().v[0].x(), 2.0, 1e-12);
}

TEST(PlaneContact, NoTunnellingAtAnyStepSize) {
  // Fast particles fired at a thin bounded plane from random places with steps from 1e-4 s to
  // 2 s: every one whose straight path crosses the rectangle must end on its starting side.
  std::mt19937_64 rng(7);
  auto u = [&](double a, double b) { return a + (b - a) * static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  const BoundedPlane wall = make_bounded_plane(Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec2(1, 1), 0.0);
  int crossing_paths = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Scene s;
    s.integrator = static_cast<IntegratorKind>(trial % 4);
    s.dt = std::pow(10.0, u(-4, std::log10(2.0)));
    const double z0 = u(0.01, 3.0);
    const Vec3 x0(u(-0.9, 0.9), u(-0.9, 0.9), z0);
    const Vec3 v0(u(-1, 1), u(-1, 1), -u(1, 1000));
    s.particles.add(x0, v0, 1.0, u(0, 1), false);
    s.planes.push_back(wall);
    const double t_hit = z0 / -v0.z();
    const Vec3 at_hit = x0 + t_hit * v0;
    if (std::abs(at_hit.x()) > 1 || std::abs(at_hit.y()) > 1) continue;
    ++crossing_paths;
    Simulation sim(s);
    sim.run(std::max<long long>(3, static_cast<long long>(std::ceil(2 * t_hit / s.dt))));
    EXPECT_GE(sim.particles().x[0].z(), 0.0) << "trial " << trial << " dt " << s.dt;
  }
  EXPECT_GT(crossing_paths, 200);
}

TEST(PlaneContact, CornerOfTwoPlanes) {
  // A particle thrown into the corner of a floor and a wall: both contacts are handled in one
  // step and it ends inside the corner region.
  Scene s;
  s.dt = 0.1;  // large step: the wall and the floor are both crossed within a step
  s.forces.gravity = Vec3(0, 0, -9.81);
  s.particles.add(Vec3(0.5, 0, 0.3), Vec3(-8.0, 0.0, -3.0), 1.0, 0.5, false);
  s.planes.push_back(make_bounded_plane(Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec2(5, 5), 0.2));
  s.planes.push_back(make_bounded_plane(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 1), Vec2(5, 5), 0.2));
  Simulation sim(s);
  sim.set_log_contacts(true);
  for (int i = 0; i < 100; ++i) {
    sim.step();
    ASSERT_GE(sim.particles().x[0].z(), 0.0) << "step " << i;
    ASSERT_GE(sim.particles().x[0].x(), 0.0) << "step " << i;
  }
  bool floor = false, wall = false;
  for (const auto& e : sim.contact_log()) {
    floor = floor || e.plane == 0;
    wall = wall || e.plane == 1;
  }
  EXPECT_TRUE(floor);
  EXPECT_TRUE(wall);
}

TEST(PlaneContact, EventCapIsReportedNotSilent) {
  // 30 particles landing at 30 different times within one step with a cap of 4 events.
  Scene s;
  s.dt = 0.5;
  s.contact.max_events_per_step = 4;
  s.forces.gravity = Vec3(0, 0, -9.81);
  for (int i = 0; i < 30; ++i) s.particles.add(Vec3(0.01 * i, 0, 0.05 + 0.01 * i), Vec3::Zero(), 1.0, 0.5, false);
  s.planes.push_back(make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(10, 10), 0.0));
  Simulation sim(s);
  sim.run(1);
  EXPECT_EQ(sim.contacts().cap_hits, 1);
  for (int i = 0; i < 30; ++i) EXPECT_GE(sim.particles().x[i].z(), 0.0);
}

TEST(Simulation, NonFiniteStateEndsTheRunAsUnstable) {
  // Explicit Euler on a stiff spring with a huge step blows up; the run reports the step.
  Scene s;
  s.integrator = IntegratorKind::Euler;
  s.dt = 0.5;
  s.particles.add(Vec3::Zero(), Vec3::Zero(), 0.0, 0.5, true);
  s.particles.add(Vec3(1.5, 0, 0), Vec3::Zero(), 1e-3, 0.5, false);
  s.forces.springs.push_back(Spring{0, 1, 1e6, 1.0, 0.0});
  Simulation sim(s);
  EXPECT_FALSE(sim.run(100000));
  ASSERT_TRUE(sim.instability().has_value());
  EXPECT_EQ(sim.instability()->particle, 1);
  EXPECT_GT(sim.instability()->step, 1);
  EXPECT_LT(sim.instability()->step, 100000);
  EXPECT_FALSE(sim.step());  // stays stopped
}

}  // namespace
}  // namespace tecido
