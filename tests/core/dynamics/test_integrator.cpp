// Integrators against analytic solutions: free fall (exact discrete formulas) and the
// harmonic oscillator (observed global order from step halving).
#include "core/dynamics/force_model.h"
#include "core/dynamics/integrator.h"
#include "core/simulation/simulation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido {
namespace {

const IntegratorKind kAll[] = {IntegratorKind::Euler, IntegratorKind::Symplectic, IntegratorKind::Midpoint,
                               IntegratorKind::RK4};

Scene free_fall_scene(IntegratorKind k, double h, long long steps) {
  Scene s;
  s.integrator = k;
  s.dt = h;
  s.steps = steps;
  s.forces.gravity = Vec3(0, 0, -9.81);
  s.particles.add(Vec3(0.3, -0.2, 5.0), Vec3(1.0, 0.5, 2.0), 2.0, 0.5, false);
  return s;
}

// Free fall: midpoint and RK4 are exact for constant acceleration; explicit Euler lags the
// parabola by g h t / 2 and symplectic Euler leads it by the same amount (closed forms of the
// discrete recurrences: x_n = x0 + v0 t + g t^2/2 -/+ g h t/2).
TEST(Integrator, FreeFallMatchesAnalyticForEveryMethod) {
  const double h = 0.01;
  const long long n = 200;
  const double t = h * n;
  const Vec3 x0(0.3, -0.2, 5.0), v0(1.0, 0.5, 2.0), g(0, 0, -9.81);
  for (IntegratorKind k : kAll) {
    Simulation sim(free_fall_scene(k, h, n));
    sim.run(n);
    Vec3 expected = x0 + v0 * t + 0.5 * g * t * t;
    if (k == IntegratorKind::Euler) expected -= 0.5 * g * h * t;
    if (k == IntegratorKind::Symplectic) expected += 0.5 * g * h * t;
    EXPECT_LT((sim.particles().x[0] - expected).norm(), 1e-11) << integrator_name(k);
    EXPECT_LT((sim.particles().v[0] - (v0 + g * t)).norm(), 1e-11) << integrator_name(k);
  }
}

// Error at time T of the undamped oscillator x'' = -omega^2 (x - l), x(0) = l + A, v(0) = 0.
double oscillator_error(IntegratorKind k, double h, double T) {
  Scene s;
  s.integrator = k;
  s.dt = h;
  s.particles.add(Vec3::Zero(), Vec3::Zero(), 0.0, 1.0, true);
  s.particles.add(Vec3(1.5, 0, 0), Vec3::Zero(), 1.0, 1.0, false);
  s.forces.springs.push_back(Spring{0, 1, 4.0, 1.0, 0.0});
  const long long n = std::llround(T / h);
  Simulation sim(s);
  sim.run(n);
  const double t = n * h;
  const double x = 1.0 + 0.5 * std::cos(2.0 * t);
  const double v = -1.0 * std::sin(2.0 * t);
  return std::hypot(sim.particles().x[1].x() - x, (sim.particles().v[1].x() - v) / 2.0);
}

TEST(Integrator, HarmonicOscillatorObservedOrder) {
  struct Case {
    IntegratorKind k;
    double expected;
    double h0;
  };
  // h0 chosen inside each method's asymptotic range: small enough for the leading error term
  // to dominate, large enough to stay clear of round-off over 3 halvings.
  const Case cases[] = {{IntegratorKind::Euler, 1.0, 0.002},
                        {IntegratorKind::Symplectic, 1.0, 0.002},
                        {IntegratorKind::Midpoint, 2.0, 0.01},
                        {IntegratorKind::RK4, 4.0, 0.05}};
  const double T = 2.0;
  for (const Case& c : cases) {
    double prev = oscillator_error(c.k, c.h0, T);
    for (int halving = 1; halving <= 3; ++halving) {
      const double e = oscillator_error(c.k, c.h0 / std::pow(2.0, halving), T);
      const double order = std::log2(prev / e);
      EXPECT_NEAR(order, c.expected, 0.15) << integrator_name(c.k) << " halving " << halving;
      prev = e;
    }
  }
}

TEST(Integrator, EvaluationsPerStepAndNames) {
  EXPECT_EQ(evaluations_per_step(IntegratorKind::Euler), 1);
  EXPECT_EQ(evaluations_per_step(IntegratorKind::Midpoint), 2);
  EXPECT_EQ(evaluations_per_step(IntegratorKind::RK4), 4);
  for (IntegratorKind k : kAll) EXPECT_EQ(parse_integrator(integrator_name(k)), k);
  EXPECT_FALSE(parse_integrator("verlet").has_value());
}

// Springs are internal: their forces sum to zero whatever the configuration.
TEST(ForceModel, SpringForcesSumToZero) {
  std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(1.1, 0.2, -0.3), Vec3(0.4, 1.7, 0.5), Vec3(-0.8, 0.3, 2.0)};
  std::vector<Vec3> v = {Vec3(0.1, 0, 0), Vec3(0, -0.3, 0.2), Vec3(1, 1, 0), Vec3(0, 0, -2)};
  std::vector<Spring> springs = {{0, 1, 10, 1, 0.5}, {1, 2, 3, 0.5, 0}, {2, 3, 7, 2, 0.1}, {0, 3, 1, 0.2, 0}};
  std::vector<Vec3> f;
  accumulate_spring_forces(springs, x, v, f);
  Vec3 sum = Vec3::Zero();
  for (const auto& fi : f) sum += fi;
  EXPECT_LT(sum.norm(), 1e-13);
  // Eq. 10 by hand for the first spring alone: f_0 = ks (|x01| - l) x01/|x01| + damping term.
  std::vector<Vec3> f1;
  accumulate_spring_forces({springs[0]}, x, v, f1);
  const Vec3 d = x[1] - x[0];
  const Vec3 u = d.normalized();
  const Vec3 expected = (10.0 * (d.norm() - 1.0) + 0.5 * (v[1] - v[0]).dot(u)) * u;
  EXPECT_LT((f1[0] - expected).norm(), 1e-14);
  EXPECT_LT((f1[1] + expected).norm(), 1e-14);
}

TEST(ForceModel, AbsentForcesCostNothingAndPinnedParticlesStay) {
  Scene s;
  s.dt = 0.1;
  s.particles.add(Vec3(1, 2, 3), Vec3(0.5, 0, 0), 1.0, 0.5, false);
  s.particles.add(Vec3(0, 0, 0), Vec3(9, 9, 9), 1.0, 0.5, true);  // pinned: velocity dropped
  Simulation sim(s);
  sim.run(10);
  // No gravity, wind or drag named: uniform motion.
  EXPECT_LT((sim.particles().x[0] - Vec3(1.5, 2, 3)).norm(), 1e-14);
  EXPECT_EQ(sim.particles().x[1], Vec3(0, 0, 0));
}

TEST(ForceModel, LinearDragTerminalVelocity) {
  // m v' = m g - c v  ->  v(t) = v_inf (1 - exp(-c t / m)), v_inf = m g / c.
  Scene s;
  s.integrator = IntegratorKind::RK4;
  s.dt = 0.001;
  s.forces.gravity = Vec3(0, 0, -9.81);
  s.forces.air_drag = 0.5;
  s.particles.add(Vec3::Zero(), Vec3::Zero(), 2.0, 0.5, false);
  Simulation sim(s);
  sim.run(3000);
  const double vinf = -2.0 * 9.81 / 0.5;
  EXPECT_NEAR(sim.particles().v[0].z(), vinf * (1.0 - std::exp(-0.5 * 3.0 / 2.0)), 1e-9);
}

TEST(ForceModel, SwirlWindKeepsMagnitudeAndCircles) {
  Wind w;
  w.force = Vec3(0.1, 0, 0.05);
  w.swirl = true;
  w.axis = Vec3(0, 0, 1);
  w.rate = M_PI / 2.0;
  w.phase = 0.0;
  const double mag = w.force.norm();
  EXPECT_NEAR(w.at(0.0).norm(), mag, 1e-15);
  EXPECT_LT((w.at(0.0) - Vec3(mag, 0, 0)).norm(), 1e-15);
  EXPECT_LT((w.at(1.0) - Vec3(0, mag, 0)).norm(), 1e-15);  // a quarter turn, counter-clockwise about z
  EXPECT_LT((w.at(2.0) - Vec3(-mag, 0, 0)).norm(), 1e-15);
}

}  // namespace
}  // namespace tecido
