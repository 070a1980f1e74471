// The plane suite's theory (comparisons/suites/plane/theory.*) against values worked by hand and
// against the equations they solve; "exact for constant acceleration" against core's integrators
// run on a parabola.
#include "comparisons/suites/plane/theory.h"

#include "core/simulation/simulation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::plane {
namespace {

TEST(PlaneTheory, ContactTimeIsTheRootOfTheParabola) {
  // Worked by hand: from rest at g/2 m it lands after 1 s at g m/s; thrown up at g m/s from the floor,
  // it is back after 2 s.
  EXPECT_NEAR(contact_time(4.905, 0.0, 9.81), 1.0, 1e-15);
  EXPECT_NEAR(impact_speed(4.905, 0.0, 9.81), 9.81, 1e-14);
  EXPECT_NEAR(contact_time(0.0, 9.81, 9.81), 2.0, 1e-15);
  for (double z0 : {0.2, 1.0, 5.0})
    for (double vz0 : {-3.0, 0.0, 2.5}) {
      const double g = 9.81, t = contact_time(z0, vz0, g);
      EXPECT_GT(t, 0.0);
      EXPECT_NEAR(z0 + vz0 * t - 0.5 * g * t * t, 0.0, 1e-13) << z0 << " " << vz0;
      EXPECT_NEAR(std::abs(vz0 - g * t), impact_speed(z0, vz0, g), 1e-13);
    }
}

TEST(PlaneTheory, ReboundApexAndFlightFromTheReboundSpeed) {
  // From rest at 2 m with k = 0.5: impact speed sqrt(2 g 2), rebound at half of it, which climbs
  // (k v)^2 / 2g = 0.5 m and stays aloft 2 k v / g.
  const double g = 9.81, v = std::sqrt(4.0 * g);
  EXPECT_NEAR(rebound_apex(2.0, 0.5), 0.5, 1e-15);
  EXPECT_NEAR(rebound_apex(2.0, 0.5), (0.5 * v) * (0.5 * v) / (2.0 * g), 1e-15);
  EXPECT_NEAR(rebound_flight(2.0, 0.5, g), 2.0 * 0.5 * v / g, 1e-15);
}

/// |z(T) - parabola(T)| of a free particle integrated with k at step h for n steps.
double parabola_error(IntegratorKind k, double h, int n) {
  Scene s;
  s.integrator = k;
  s.dt = h;
  s.forces.gravity = Vec3(0, 0, -9.81);
  s.particles.add(Vec3(0, 0, 3.0), Vec3(0, 0, 1.5), 1.0, 0.5, false);
  Simulation sim(s);
  for (int i = 0; i < n; ++i) sim.step();
  const double T = h * n;
  return std::abs(sim.particles().x[0].z() - (3.0 + 1.5 * T - 0.5 * 9.81 * T * T));
}

TEST(PlaneTheory, ExactForConstantAccelerationMatchesCoresIntegrators) {
  for (IntegratorKind k : {IntegratorKind::Euler, IntegratorKind::Symplectic, IntegratorKind::Midpoint, IntegratorKind::RK4}) {
    const double err = parabola_error(k, 0.01, 50);
    if (exact_for_constant_acceleration(k)) {
      EXPECT_LT(err, 1e-13) << integrator_name(k);
    } else {
      EXPECT_GT(err, 1e-4) << integrator_name(k);  // O(h) T g / 2 ~ 2.5e-3
    }
  }
  EXPECT_TRUE(exact_for_constant_acceleration(IntegratorKind::Midpoint));
  EXPECT_FALSE(exact_for_constant_acceleration(IntegratorKind::Symplectic));
}

}  // namespace
}  // namespace tecido::suites::plane
