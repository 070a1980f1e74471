// The stability suite's runs and bisection (comparisons/suites/stability/oscillator.*): a planted
// threshold, the known limits of symplectic Euler and RK4, and Euler's growth per step.
#include "comparisons/suites/stability/oscillator.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::stability {
namespace {

TEST(FindMaxStableStep, BracketsAndBisectsAPlantedThreshold) {
  // Stable exactly for h <= 0.7: from 0.1 it doubles to 0.2, 0.4, 0.8 (unstable), then bisects.
  int calls = 0;
  const StableStep up = find_max_stable_step([&](double h) { return ++calls, h <= 0.7; }, 0.1, 1e-9);
  ASSERT_TRUE(up.found);
  EXPECT_LE(up.h, 0.7);
  EXPECT_GT(up.h_unstable, 0.7);
  EXPECT_LE(up.h_unstable - up.h, 1e-9 * up.h);
  EXPECT_EQ(up.runs, calls);
  // From above: halves 3.0 -> 1.5 -> 0.75 (unstable) -> 0.375 (stable).
  const StableStep down = find_max_stable_step([](double h) { return h <= 0.7; }, 3.0, 1e-9);
  ASSERT_TRUE(down.found);
  EXPECT_NEAR(down.h, 0.7, 1e-9);
  // Same predicate, same start: the same sequence of calls and the same answer, bit for bit.
  const StableStep again = find_max_stable_step([](double h) { return h <= 0.7; }, 3.0, 1e-9);
  EXPECT_EQ(again.h, down.h);
  EXPECT_EQ(again.runs, down.runs);
}

TEST(FindMaxStableStep, ReportsWhenNothingIsStable) {
  const StableStep r = find_max_stable_step([](double) { return false; }, 1.0, 1e-6, 10, 10);
  EXPECT_FALSE(r.found);
  EXPECT_EQ(r.runs, 11);
  EXPECT_DOUBLE_EQ(r.h_unstable, 1.0 / 1024.0);
}

TEST(FindMaxStableStep, StableEverywhereStopsAfterTheDoublings) {
  const StableStep r = find_max_stable_step([](double) { return true; }, 1.0, 1e-6, 5, 5);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.h, 32.0);
  EXPECT_EQ(r.runs, 6);
}

TEST(Oscillator, SymplecticLimitIsTwoOverOmega) {
  // ks = 4 N/m, m = 1 kg: omega = 2 1/s, so h_max = 1 s; to 3 digits of h omega = 2.
  const StableStep s = oscillator_max_step(IntegratorKind::Symplectic, 4.0, 1.0, 200.0, 1000.0, 1e-6);
  ASSERT_TRUE(s.found);
  EXPECT_NEAR(s.h * 2.0, 2.0, 1e-3);
  EXPECT_LE(s.h * 2.0, 2.0);  // stable below the limit only
}

TEST(Oscillator, RK4LimitIsTwoRootTwoOverOmega) {
  const StableStep s = oscillator_max_step(IntegratorKind::RK4, 1e4, 1e-2, 200.0, 1000.0, 1e-6);  // omega = 1000
  ASSERT_TRUE(s.found);
  EXPECT_NEAR(s.h * 1000.0, 2.0 * std::sqrt(2.0), 1e-2);
}

TEST(Oscillator, EulerGrowthPerStepIsItsAmplification) {
  // Euler's update is a scaled rotation of (x, v/omega): the norm grows by sqrt(1 + c^2) per step.
  const double c = 0.1;
  const OscillatorRun r = run_oscillator(IntegratorKind::Euler, 9.0, 1.0, c / 3.0, 5.0, 1e3);
  ASSERT_TRUE(r.finite);
  EXPECT_TRUE(r.bounded);
  EXPECT_EQ(r.unstable_step, 0);
  EXPECT_NEAR(r.growth_per_step, std::sqrt(1.0 + c * c), 1e-13);
  const OscillatorRun m = run_oscillator(IntegratorKind::Midpoint, 9.0, 1.0, c / 3.0, 5.0, 1e3);
  EXPECT_NEAR(m.growth_per_step, std::sqrt(1.0 + c * c * c * c / 4.0), 1e-13);
}

TEST(Oscillator, StopsAtTheBoundAndCountsTheSteps) {
  // Euler at c = 1 maps (x, v/omega) by [[1, 1], [-1, 1]]: a rotation by 45 degrees scaled by sqrt 2,
  // so x_n = 2^(n/2) cos(n pi/4) = 1, 1, 0, -2, -4, -4, 0, 8, 16: the first |x| > 10 is step 8.
  const OscillatorRun r = run_oscillator(IntegratorKind::Euler, 1.0, 1.0, 1.0, 100.0, 10.0);
  EXPECT_TRUE(r.finite);
  EXPECT_FALSE(r.bounded);
  EXPECT_EQ(r.steps, 8);
}

TEST(Oscillator, AnUnstableRunReportsItsStep) {
  // Euler at c = 10 multiplies the norm by sqrt(101) a step: 10^(1.0022 n). The spring's length is
  // sqrt(|d|^2), whose square overflows once |x| passes sqrt(DBL_MAX) = 1.3e154, i.e. from about step
  // 154 (the state turns by atan 10 a step, so |x| reaches its norm within a few steps of it); the
  // force is then inf * 0 = NaN and the velocity with it.
  const OscillatorRun r = run_oscillator(IntegratorKind::Euler, 1.0, 1.0, 10.0, 1e4, INFINITY);
  EXPECT_FALSE(r.finite);
  EXPECT_GE(r.unstable_step, 154);
  EXPECT_LE(r.unstable_step, 160);
  EXPECT_EQ(r.steps, r.unstable_step);
  EXPECT_EQ(r.growth_per_step, INFINITY);
}

TEST(StepsFor, RoundsUp) {
  EXPECT_EQ(steps_for(1.0, 1.0, 1.0), 7);    // 2 pi = 6.28
  EXPECT_EQ(steps_for(3.0, 2.0, 0.5), 19);   // 3 pi / 0.5 = 18.85
}

}  // namespace
}  // namespace tecido::suites::stability
