// The drift suite's theory (comparisons/suites/drift/theory.h): the Butcher tableaux, Cooper's
// change of angular momentum checked against one step of core's integrators and against explicit
// Euler's hand-worked h^2 sum v x f, symplectic Euler's exact conservation, the fall time.
#include "comparisons/suites/drift/theory.h"

#include "comparisons/suites/drift/invariants.h"
#include "core/dynamics/force_model.h"
#include "core/simulation/simulation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::drift {
namespace {

// Three free particles on two springs, stretched, moving off the springs' lines.
Scene three_body() {
  Scene s;
  s.particles.add(Vec3(0, 0, 0), Vec3(0.3, -0.2, 0.1), 1.0, 1.0, false);
  s.particles.add(Vec3(1.2, 0.1, 0), Vec3(-0.1, 0.4, 0.0), 2.0, 1.0, false);
  s.particles.add(Vec3(0.5, 1.1, 0.2), Vec3(0.0, -0.3, 0.2), 0.5, 1.0, false);
  s.forces.springs.push_back(Spring{0, 1, 9.0, 1.0, 0.0});
  s.forces.springs.push_back(Spring{1, 2, 4.0, 0.8, 0.0});
  s.dt = 0.05;
  return s;
}

TEST(DriftTheory, TableausAreTheDocumentedMethods) {
  EXPECT_FALSE(runge_kutta_tableau(IntegratorKind::Symplectic).has_value());
  for (IntegratorKind k : {IntegratorKind::Euler, IntegratorKind::Midpoint, IntegratorKind::RK4}) {
    const Tableau t = *runge_kutta_tableau(k);
    ASSERT_EQ(static_cast<int>(t.b.size()), evaluations_per_step(k));
    double sum = 0.0;
    for (double b : t.b) sum += b;
    EXPECT_DOUBLE_EQ(sum, 1.0);
    for (std::size_t i = 0; i < t.a.size(); ++i)
      for (std::size_t j = i; j < t.a.size(); ++j) EXPECT_EQ(t.a[i][j], 0.0) << "explicit: a[" << i << "][" << j << "]";
  }
  EXPECT_TRUE(conserves_angular_momentum(IntegratorKind::Symplectic));
  EXPECT_FALSE(conserves_angular_momentum(IntegratorKind::RK4));
}

TEST(DriftTheory, ExplicitEulerChangeIsHSquaredSumOfVCrossF) {
  const Scene s = three_body();
  std::vector<Vec3> f;
  accumulate_spring_forces(s.forces.springs, s.particles.x, s.particles.v, f);
  Vec3 expected = Vec3::Zero();
  for (std::size_t i = 0; i < f.size(); ++i) expected += s.particles.v[i].cross(f[i]);
  expected *= s.dt * s.dt;
  const Vec3 got = angular_momentum_change(*runge_kutta_tableau(IntegratorKind::Euler), s.forces.springs,
                                           s.particles.inv_mass, s.particles.x, s.particles.v, s.dt);
  EXPECT_NEAR((got - expected).norm(), 0.0, 1e-15);
  EXPECT_GT(expected.norm(), 1e-4);  // a change worth predicting
}

TEST(DriftTheory, CooperPredictsOneStepOfEachCoreIntegrator) {
  for (IntegratorKind k : {IntegratorKind::Euler, IntegratorKind::Symplectic, IntegratorKind::Midpoint, IntegratorKind::RK4}) {
    Scene s = three_body();
    s.integrator = k;
    const auto& w = s.particles.inv_mass;
    const Vec3 l0 = angular_momentum(w, s.particles.x, s.particles.v);
    const auto t = runge_kutta_tableau(k);
    const Vec3 predicted = t ? angular_momentum_change(*t, s.forces.springs, w, s.particles.x, s.particles.v, s.dt) : Vec3::Zero();
    Simulation sim(s);
    ASSERT_TRUE(sim.step());
    const Vec3 change = angular_momentum(w, sim.particles().x, sim.particles().v) - l0;
    EXPECT_NEAR((change - predicted).norm(), 0.0, 1e-14) << integrator_name(k);
    if (k != IntegratorKind::Symplectic) {
      EXPECT_GT(change.norm(), 1e-9) << integrator_name(k) << " changes L: a real test";
    }
  }
}

TEST(DriftTheory, CooperNeedsFreeParticles) {
  Scene s = three_body();
  s.particles.inv_mass[0] = 0.0;
  EXPECT_THROW(angular_momentum_change(*runge_kutta_tableau(IntegratorKind::Euler), s.forces.springs,
                                       s.particles.inv_mass, s.particles.x, s.particles.v, s.dt),
               std::invalid_argument);
}

TEST(DriftTheory, FallTimeAndLoadRatio) {
  EXPECT_DOUBLE_EQ(fall_time(0.5, 9.81), std::sqrt(1.0 / 9.81));
  EXPECT_DOUBLE_EQ(fall_time(4.9, 9.8), 1.0);
  EXPECT_DOUBLE_EQ(classic_sag_ratio(2.0), 0.5);
}

}  // namespace
}  // namespace tecido::suites::drift
