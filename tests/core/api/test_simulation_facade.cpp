// The public engine (include/tecido/simulation.h) against closed forms: a free particle under
// gravity (each integrator's own recurrence, solved), a spring pair (the harmonic oscillator, each
// integrator's order), a ball bouncing on a plane (time of contact, restitution), a pinned cloth,
// divergence, and the arguments it refuses.
#include <tecido/simulation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace {

using tecido::Vec3;
namespace tc = tecido::core;

const Vec3 kG(0.0, 0.0, -9.81);

/// x after n steps of h from x0, v0 under constant acceleration g:
///  explicit Euler   x_n = x0 + n h v0 + h^2 g n (n - 1) / 2
///  symplectic Euler x_n = x0 + n h v0 + h^2 g n (n + 1) / 2
///  midpoint, RK4    x_n = x0 + t v0 + g t^2 / 2 (exact for a constant acceleration)
Vec3 free_fall(tc::Integrator k, const Vec3& x0, const Vec3& v0, double h, long long n) {
  const double nn = static_cast<double>(n);
  const double t = nn * h;
  if (k == tc::Integrator::Euler) return x0 + t * v0 + h * h * nn * (nn - 1) / 2 * kG;
  if (k == tc::Integrator::Symplectic) return x0 + t * v0 + h * h * nn * (nn + 1) / 2 * kG;
  return x0 + t * v0 + 0.5 * t * t * kG;
}

TEST(SimulationFacade, FreeParticleFollowsEachIntegratorsClosedForm) {
  const Vec3 x0(1, 2, 30), v0(0.5, -0.25, 4);
  const double h = 0.01;
  const long long n = 200;
  for (tc::Integrator k : {tc::Integrator::Euler, tc::Integrator::Symplectic, tc::Integrator::Midpoint,
                           tc::Integrator::RK4}) {
    tc::Scene scene;
    scene.set_integrator(k).set_dt(h).set_gravity(kG);
    scene.add_particle(x0, v0, 2.0);
    tc::Simulation sim(scene);
    EXPECT_TRUE(sim.run(n));
    const Vec3 want = free_fall(k, x0, v0, h, n);
    EXPECT_LT((sim.positions()[0] - want).norm(), 1e-11) << static_cast<int>(k);
    EXPECT_LT((sim.velocities()[0] - (v0 + n * h * kG)).norm(), 1e-11);
    EXPECT_DOUBLE_EQ(sim.time(), n * h);
    EXPECT_EQ(sim.steps_done(), n);
    EXPECT_FALSE(sim.diverged());
  }
}

/// Two free particles of 1 kg joined by a spring (ks = 9, l = 1), released at separation 1.2 with
/// particle 0 moving at 0.5 m/s: the separation is d(t) = 1 + 0.2 cos(w t) - (0.5 / w) sin(w t),
/// w = sqrt(18), and the centre of mass moves at 0.25 m/s. The error at t = 1 s.
double spring_pair_error(tc::Integrator k, double h) {
  tc::Scene scene;
  scene.set_integrator(k).set_dt(h);
  const int a = scene.add_particle(Vec3(0, 0, 0), Vec3(0.5, 0, 0), 1.0);
  const int b = scene.add_particle(Vec3(1.2, 0, 0), Vec3::Zero(), 1.0);
  scene.add_spring(a, b, 9.0, 1.0);
  tc::Simulation sim(scene);
  sim.run(std::llround(1.0 / h));
  const double t = sim.time(), w = std::sqrt(18.0);
  const double d = 1.0 + 0.2 * std::cos(w * t) - 0.5 / w * std::sin(w * t);
  const double xa = sim.positions()[a].x(), xb = sim.positions()[b].x();
  return std::abs(xb - xa - d) + std::abs(0.5 * (xa + xb) - (0.6 + 0.25 * t));
}

TEST(SimulationFacade, SpringPairConvergesAtEachIntegratorsOrder) {
  struct Case {
    tc::Integrator k;
    double order, h;
  } cases[] = {{tc::Integrator::Euler, 1, 0.0005},
               {tc::Integrator::Symplectic, 1, 0.0005},
               {tc::Integrator::Midpoint, 2, 0.004},
               {tc::Integrator::RK4, 4, 0.02}};
  for (const Case& c : cases) {
    const double e1 = spring_pair_error(c.k, c.h), e2 = spring_pair_error(c.k, c.h / 2);
    EXPECT_NEAR(std::log2(e1 / e2), c.order, 0.15) << static_cast<int>(c.k) << " e1=" << e1 << " e2=" << e2;
  }
}

TEST(SimulationFacade, BallBouncesOffAPlaneAtTheRightTimeAndSpeed) {
  // Dropped from 1 m onto the floor z = 0 (k = 0.5): contact at t* = sqrt(2 / 9.81), impact speed
  // g t*, rebound speed k g t*. RK4 is exact between contacts (constant acceleration), so what
  // remains is the bisection's bracket (dt 2^-20 by default) on the time of contact.
  const double h = 0.01, k = 0.5;
  tc::Scene scene;
  scene.set_integrator(tc::Integrator::RK4).set_dt(h).set_gravity(kG);
  scene.add_plane(tecido::Rectangle{}, 0.0);  // the 2 m x 2 m square at z = 0
  scene.add_particle(Vec3(0.1, 0.2, 1.0), Vec3::Zero(), 1.0, k);
  tc::Simulation sim(scene);
  const double t_star = std::sqrt(2.0 / 9.81);
  const long long before = static_cast<long long>(std::floor(t_star / h));
  sim.run(before);
  EXPECT_EQ(sim.contacts().events, 0);
  sim.step();  // the step holding the contact
  EXPECT_EQ(sim.contacts().events, 1);
  EXPECT_EQ(sim.contacts().elastic, 1);
  const double t = sim.time();
  // After the contact: rising at k g t* less the gravity since t*.
  const double vz = k * 9.81 * t_star - 9.81 * (t - t_star);
  const double z = k * 9.81 * t_star * (t - t_star) - 0.5 * 9.81 * (t - t_star) * (t - t_star);
  EXPECT_NEAR(sim.velocities()[0].z(), vz, 1e-5);
  EXPECT_NEAR(sim.positions()[0].z(), z, 1e-6);
  EXPECT_GT(sim.positions()[0].z(), 0.0);
  // Never below the floor for 3 s of bounces (particles remember their side).
  for (int s = 0; s < 300; ++s) {
    sim.step();
    ASSERT_GE(sim.positions()[0].z(), 0.0) << "step " << sim.steps_done();
  }
}

TEST(SimulationFacade, ClothKeepsItsPinnedCornersAndItsNumbering) {
  tc::ClothGrid g;
  g.rows = 5;
  g.cols = 4;
  g.spacing = 0.25;
  g.origin = Vec3(0, 0, 2);
  g.axis_v = -Vec3::UnitZ();
  g.stiffness = 200;
  g.bend_stiffness = 50;
  g.pins = {{0, 0}, {0, 3}};
  tc::Scene scene;
  scene.set_gravity(kG).set_dt(0.002);
  scene.add_particle(Vec3(5, 5, 5), Vec3::Zero(), 1.0);  // one particle before the cloth
  const int first = scene.add_cloth(g);
  EXPECT_EQ(first, 1);
  EXPECT_EQ(scene.particle_count(), 1u + 20u);
  EXPECT_EQ(scene.triangles().size(), 2u * 4u * 3u);
  // One edge apart: 5 x 3 horizontal, 4 x 4 vertical, 4 x 3 per diagonal; two apart: 5 x 2, 3 x 4, 3 x 2 each.
  EXPECT_EQ(scene.spring_count(), 15u + 16u + 12u + 12u + 10u + 12u + 6u + 6u);
  // Node (r, c) = first + r cols + c at origin + c spacing axis_u + r spacing axis_v.
  EXPECT_EQ(scene.positions()[first + 2 * 4 + 3], Vec3(0.75, 0, 1.5));
  tc::Simulation sim(scene);
  double lowest = 1.0;  // node (4, 1), the free bottom row, starts at z = 1
  for (int s = 0; s < 500; ++s) {
    ASSERT_TRUE(sim.step());
    lowest = std::min(lowest, sim.positions()[first + 4 * 4 + 1].z());
  }
  EXPECT_EQ(sim.positions()[first], Vec3(0, 0, 2));
  EXPECT_EQ(sim.positions()[first + 3], Vec3(0.75, 0, 2));
  EXPECT_EQ(sim.velocities()[first], Vec3::Zero());
  EXPECT_LT(lowest, 1.0 - 1e-3);  // it fell, held by the springs (undamped: it swings back up)
}

TEST(SimulationFacade, AStiffSpringWithAHugeStepDiverges) {
  tc::Scene scene;
  scene.set_integrator(tc::Integrator::Euler).set_dt(1.0);
  const int a = scene.add_particle(Vec3(0, 0, 0), Vec3::Zero(), 1.0);
  const int b = scene.add_particle(Vec3(1.5, 0, 0), Vec3::Zero(), 1.0);
  scene.add_spring(a, b, 1e6, 1.0);
  tc::Simulation sim(scene);
  EXPECT_FALSE(sim.run(10000));
  ASSERT_TRUE(sim.diverged());
  const tc::Divergence& d = *sim.divergence();
  EXPECT_GT(d.step, 1);
  EXPECT_EQ(d.step, sim.steps_done());
  EXPECT_TRUE(d.quantity == "position" || d.quantity == "velocity");
  EXPECT_FALSE(sim.step());
  EXPECT_FALSE(sim.run(0));
  EXPECT_EQ(sim.steps_done(), d.step);
}

/// What `call` throws, as text ("" when it does not throw std::invalid_argument).
template <class F>
std::string refusal(F call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SimulationFacade, BadArgumentsAreRefusedWithTheFunctionAndTheProblem) {
  tc::Scene s;
  EXPECT_EQ(refusal([&] { s.set_dt(0.0); }), "tecido::core::Scene::set_dt: dt must be > 0 and finite, got 0");
  EXPECT_EQ(refusal([&] { s.add_particle(Vec3(0, 0, NAN), Vec3::Zero(), 1.0); }),
            "tecido::core::Scene::add_particle: position must be finite");
  EXPECT_EQ(refusal([&] { s.add_particle(Vec3::Zero(), Vec3::Zero(), 1.0, 1.5); }),
            "tecido::core::Scene::add_particle: elasticity must be in [0, 1], got 1.5");
  EXPECT_EQ(refusal([&] { s.add_spring(0, 1, 1.0); }),
            "tecido::core::Scene::add_spring: particle index out of range [0, 0): 0, 1");
  tc::ClothGrid g;
  g.pins = {{2, 0}};
  EXPECT_EQ(refusal([&] { s.add_cloth(g); }), "tecido::core::Scene::add_cloth: pin (2, 0) is outside the 2 x 2 grid");
  EXPECT_EQ(refusal([&] { s.set_self_collision({}); }),
            "tecido::core::Scene::set_self_collision: self-collision needs a cloth (add it first)");
  tecido::Rectangle r;
  r.forward = r.normal;
  EXPECT_EQ(refusal([&] { s.add_plane(r); }), "tecido::core::Scene::add_plane: forward is parallel to the normal");
  EXPECT_EQ(s.particle_count(), 0u);  // nothing half added
  EXPECT_EQ(refusal([&] { tc::Simulation sim(s); }), "tecido::core::Simulation: the scene has no particles");
  tc::Sphere bad_ball;
  bad_ball.radius = -1.0;
  EXPECT_EQ(refusal([&] { s.add_sphere(bad_ball); }), "tecido::core::Scene::add_sphere: radius must be > 0 and finite, got -1");
  bad_ball.radius = 1.0;
  bad_ball.friction = 2.0;
  EXPECT_EQ(refusal([&] { s.add_sphere(bad_ball); }), "tecido::core::Scene::add_sphere: friction must be in [0, 1], got 2");
  tc::Box bad_box;
  bad_box.velocity = Vec3(INFINITY, 0, 0);
  EXPECT_EQ(refusal([&] { s.add_box(bad_box); }), "tecido::core::Scene::add_box: velocity must be finite");
  bad_box.velocity = Vec3::Zero();
  bad_box.orientation(0, 0) = -1.0;
  EXPECT_EQ(refusal([&] { s.add_box(bad_box); }),
            "tecido::core::Scene::add_box: orientation must be a rotation (orthonormal columns, determinant 1)");
  bad_box.orientation(0, 0) = 1.0;
  bad_box.elasticity = -0.5;
  EXPECT_EQ(refusal([&] { s.add_box(bad_box); }), "tecido::core::Scene::add_box: elasticity must be in [0, 1], got -0.5");
  tc::Sphere ball;
  ball.radius = 1.0;
  s.add_sphere(ball);
  s.add_particle(Vec3(0.5, 0, 0), Vec3::Zero(), 1.0);
  EXPECT_EQ(refusal([&] { tc::Simulation sim(s); }),
            "tecido::core::Simulation: free particle 0 starts inside sphere 0 (spheres and boxes are solid)");
}

}  // namespace
