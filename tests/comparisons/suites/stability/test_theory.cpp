// The stability suite's theory (comparisons/suites/stability/theory.*) against values worked by hand.
#include "comparisons/suites/stability/theory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tecido::suites::stability {
namespace {

TEST(Amplification, MatchesTheLinearTheory) {
  EXPECT_DOUBLE_EQ(amplification(IntegratorKind::Symplectic, 1.999), 1.0);
  EXPECT_GT(amplification(IntegratorKind::Symplectic, 2.001), 1.0);
  EXPECT_NEAR(amplification(IntegratorKind::RK4, 2.0 * std::sqrt(2.0)), 1.0, 1e-12);
  EXPECT_LT(amplification(IntegratorKind::RK4, 2.8), 1.0);
  EXPECT_GT(amplification(IntegratorKind::RK4, 2.85), 1.0);
  for (double c : {1e-3, 0.1, 1.0}) {
    EXPECT_GT(amplification(IntegratorKind::Euler, c), 1.0);
    EXPECT_GT(amplification(IntegratorKind::Midpoint, c), 1.0);
  }
}

TEST(Amplification, HandValues) {
  // Euler at c = 1: |1 + i| = sqrt 2. Midpoint at c = 2: |1 + 2i - 2| = |-1 + 2i| = sqrt 5.
  EXPECT_DOUBLE_EQ(amplification(IntegratorKind::Euler, 1.0), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(amplification(IntegratorKind::Midpoint, 2.0), std::sqrt(5.0));
  // RK4 at c = 1: 1 - 1/2 + 1/24 = 13/24 real, 1 - 1/6 = 5/6 imaginary; |R|^2 = 1 - 1/72 + 1/576 = 569/576.
  EXPECT_NEAR(amplification(IntegratorKind::RK4, 1.0), std::sqrt(569.0 / 576.0), 1e-15);
  // Symplectic at c = 3: trace 2 - 9 = -7, determinant 1: eigenvalues (-7 -+ sqrt 45)/2, radius (7 + sqrt 45)/2.
  EXPECT_NEAR(amplification(IntegratorKind::Symplectic, 3.0), (7.0 + std::sqrt(45.0)) / 2.0, 1e-14);
}

TEST(StableLimit, TwoAndTwoRootTwoAndNoneForTheGrowers) {
  EXPECT_EQ(stable_limit(IntegratorKind::Symplectic), 2.0);
  EXPECT_DOUBLE_EQ(stable_limit(IntegratorKind::RK4), std::sqrt(8.0));
  EXPECT_TRUE(std::isnan(stable_limit(IntegratorKind::Euler)));
  EXPECT_TRUE(std::isnan(stable_limit(IntegratorKind::Midpoint)));
}

TEST(GrowthPerPeriod, IsTheAmplificationOverTwoPiOverCSteps) {
  // Euler at c = 1: (sqrt 2)^(2 pi) = 2^pi.
  EXPECT_NEAR(growth_per_period(IntegratorKind::Euler, 1.0), std::pow(2.0, kPi), 1e-12);
  EXPECT_DOUBLE_EQ(growth_per_period(IntegratorKind::Symplectic, 0.5), 1.0);
}

TEST(HorizonPrediction, FollowsTheSmallStepLimits) {
  // Euler: ln|R| = ln(1 + c^2)/2 ~ c^2/2, so (2 pi N / c)(c^2/2) = pi N c = ln B: c ~ ln B / (pi N).
  const double B = 1000.0, N = 1000.0;
  const double euler = horizon_prediction(IntegratorKind::Euler, N, B);
  EXPECT_NEAR(euler, std::log(B) / (kPi * N), 1e-5 * euler);
  // Midpoint: ln|R| ~ c^4/8, so pi N c^3 / 4 = ln B: c ~ (4 ln B / (pi N))^(1/3); the next term is
  // -c^8/64 in ln|R|, relative c^4/8 ~ 1e-3 at N = 1000.
  const double mid = horizon_prediction(IntegratorKind::Midpoint, N, B);
  EXPECT_NEAR(mid, std::cbrt(4.0 * std::log(B) / (kPi * N)), 1e-3 * mid);
  // Longer runs call a smaller step stable.
  EXPECT_LT(horizon_prediction(IntegratorKind::Euler, 2 * N, B), euler);
}

TEST(BoundStretchLimit, HandValues) {
  // 2 sqrt(1 - 1/B^2): B = 10 gives 2 sqrt 0.99; B = 1 leaves no room; a huge B tends to 2.
  EXPECT_DOUBLE_EQ(bound_stretch_limit(10.0), 2.0 * std::sqrt(0.99));
  EXPECT_EQ(bound_stretch_limit(1.0), 0.0);
  EXPECT_NEAR(bound_stretch_limit(1e8), 2.0, 1e-15);
  // It is where the peak 2 / sqrt(4 - c^2) of the stretched ellipse reaches B.
  const double c = bound_stretch_limit(1000.0);
  EXPECT_NEAR(2.0 / std::sqrt(4.0 - c * c), 1000.0, 1e-6);
}

TEST(OmegaMax, PairAndChainHandValues) {
  // Equal unit masses on ks = 1: the pair's relative mode sqrt(2); the chain anchor-1-1 has
  // eigenvalues (3 +- sqrt 5)/2 of [[2, -1], [-1, 1]], so omega_max is the golden ratio.
  EXPECT_DOUBLE_EQ(pair_omega_max(1.0, 1.0, 1.0), std::sqrt(2.0));
  EXPECT_NEAR(chain_omega_max(1.0, 1.0, 1.0), (1.0 + std::sqrt(5.0)) / 2.0, 1e-15);
  // A light end dominates: sqrt(ks (1 + 1e6)).
  EXPECT_DOUBLE_EQ(pair_omega_max(1.0, 1.0, 1e-6), std::sqrt(1.0 + 1e6));
  EXPECT_NEAR(pair_omega_max(1.0, 1.0, 1e-6) / pair_omega_max(1.0, 1.0, 1.0), std::sqrt(500000.5), 1e-9);
}

TEST(FloatingPoint, UlpAndUnderflowSeparation) {
  // 1e8 lies in [2^26, 2^27): its ulp is 2^(26 - 52).
  EXPECT_EQ(ulp_of(1e8), std::ldexp(1.0, -26));
  EXPECT_EQ(ulp_of(1.0), std::numeric_limits<double>::epsilon());
  const double d = underflow_separation();
  EXPECT_GT(d, 1.5e-162);
  EXPECT_LT(d, 1.6e-162);
  EXPECT_GT((1.01 * d) * (1.01 * d), 0.0);
  EXPECT_EQ((0.99 * d) * (0.99 * d), 0.0);
}

}  // namespace
}  // namespace tecido::suites::stability
