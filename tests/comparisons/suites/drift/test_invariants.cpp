// The drift suite's invariants (comparisons/suites/drift/invariants.h): the quantities on hand-worked
// states, a run's errors where the answer is known (symplectic Euler on a free two-body problem
// conserves momentum and angular momentum to round-off; explicit Euler's energy grows), an
// unstable run stopped at its step, and the JSON round trip.
#include "comparisons/suites/drift/invariants.h"

#include "comparisons/suites/drift/scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tecido::suites::drift {
namespace {

TEST(DriftInvariants, QuantitiesOnAHandWorkedState) {
  // Masses 1 and 2 (the second pinned particle, inverse mass 0, is left out).
  const std::vector<double> w = {1.0, 0.5, 0.0};
  const std::vector<Vec3> x = {Vec3(1, 0, 0), Vec3(0, 2, 0), Vec3(5, 5, 5)};
  const std::vector<Vec3> v = {Vec3(0, 3, 0), Vec3(-1, 0, 0), Vec3(9, 9, 9)};
  EXPECT_EQ(momentum(w, v), Vec3(-2, 3, 0));
  // L = 1 (1,0,0) x (0,3,0) + 2 (0,2,0) x (-1,0,0) = (0,0,3) + (0,0,4).
  EXPECT_EQ(angular_momentum(w, x, v), Vec3(0, 0, 7));
  EXPECT_DOUBLE_EQ(momentum_scale(w, v), 3.0 + 2.0);
  EXPECT_DOUBLE_EQ(angular_momentum_scale(w, x, v), 1.0 * 3.0 + 2.0 * 2.0 * 1.0);
  Scene s;
  s.particles.add(x[0], v[0], 1.0, 1.0, false);
  s.particles.add(x[1], v[1], 2.0, 1.0, false);
  s.forces.springs.push_back(Spring{0, 1, 4.0, 2.0, 0.0});  // |x01| = sqrt 5: stretched by sqrt 5 - 2
  const double stretch = std::sqrt(5.0) - 2.0;
  EXPECT_NEAR(energy(s, s.particles.x, s.particles.v), 0.5 * 9.0 + 0.5 * 2.0 * 1.0 + 0.5 * 4.0 * stretch * stretch, 1e-15);
}

TEST(DriftInvariants, SymplecticConservesAndEulerGrows) {
  Settings st;
  st.steps = 4000;
  const Scene two_body = conservative_scenes(1).at(0).scene;
  const InvariantRun sym = run_invariants(two_body, IntegratorKind::Symplectic, st);
  EXPECT_EQ(sym.unstable_at_step, 0);
  EXPECT_LT(sym.momentum_error, 1e-14);
  EXPECT_LT(sym.angular_momentum_error, 1e-13);
  EXPECT_EQ(sym.angular_momentum_vs_theory, sym.angular_momentum_error);  // no predicted change
  EXPECT_EQ(sym.energy_curve.size(), 4u);                                 // every plot_every = 1000 steps
  const InvariantRun eul = run_invariants(two_body, IntegratorKind::Euler, st);
  EXPECT_GT(eul.last_over_first_half, 1.0);
  EXPECT_GT(eul.growth_rate, 0.0);
  EXPECT_GT(eul.angular_momentum_error, 1e-6);      // explicit Euler changes L ...
  EXPECT_LT(eul.angular_momentum_vs_theory, 1e-13);  // ... by what theory predicts
}

TEST(DriftInvariants, AnUnstableRunStopsAtItsStep) {
  Scene s = conservative_scenes(1).at(0).scene;
  s.dt = 50.0;  // omega h far above 2: explicit Euler overflows
  Settings st;
  st.steps = 5000;
  const InvariantRun r = run_invariants(s, IntegratorKind::Euler, st);
  EXPECT_GT(r.unstable_at_step, 0);
  EXPECT_LT(r.unstable_at_step, 5000);
}

TEST(DriftInvariants, JsonRoundTripKeepsNaN) {
  InvariantRun r;
  r.steps = 10;
  r.unstable_at_step = 3;
  r.growth_rate = std::numeric_limits<double>::quiet_NaN();
  r.momentum_error = 1.0 / 3.0;
  r.energy_curve = {{0.5, std::numeric_limits<double>::infinity()}};
  const InvariantRun b = invariant_from_json(io::Json::parse(invariant_json(r).dump()));
  EXPECT_EQ(b.unstable_at_step, 3);
  EXPECT_TRUE(std::isnan(b.growth_rate));
  EXPECT_EQ(b.momentum_error, 1.0 / 3.0);
  ASSERT_EQ(b.energy_curve.size(), 1u);
  EXPECT_TRUE(std::isinf(b.energy_curve[0][1]));
}

}  // namespace
}  // namespace tecido::suites::drift
