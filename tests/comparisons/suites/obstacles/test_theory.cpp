// The obstacles suite's closed forms against hand-worked numbers.
#include "comparisons/suites/obstacles/theory.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::obstacles {

TEST(ObstaclesTheory, FallTimeIsSqrtTwoHOverG) {
  // 1 m at 9.81 m/s^2: sqrt(2 / 9.81) = 0.45152364...
  EXPECT_NEAR(fall_time(1.0, 9.81), 0.4515236409857309, 1e-15);
  // 4.905 m at 9.81: exactly 1 s.
  EXPECT_NEAR(fall_time(4.905, 9.81), 1.0, 1e-15);
}

TEST(ObstaclesTheory, ReboundApexIsKSquaredH) {
  EXPECT_DOUBLE_EQ(rebound_apex(1.0, 0.8), 0.64);
  EXPECT_DOUBLE_EQ(rebound_apex(2.5, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(rebound_apex(2.5, 1.0), 2.5);
}

TEST(ObstaclesTheory, SlideDistanceFollowsTheSeedsFrictionLawStepByStep) {
  // a = 2, mu = 0.5, h = 0.1 by hand: v1 = a h = 0.2, v2 = 0.5 * 0.2 + 0.2 = 0.3,
  // v3 = 0.5 * 0.3 + 0.2 = 0.35; x3 = 0.1 * (0.2 + 0.3 + 0.35) = 0.085.
  EXPECT_NEAR(slide_distance(2.0, 0.5, 0.1, 1), 0.02, 1e-15);
  EXPECT_NEAR(slide_distance(2.0, 0.5, 0.1, 2), 0.05, 1e-15);
  EXPECT_NEAR(slide_distance(2.0, 0.5, 0.1, 3), 0.085, 1e-15);
  // Frictionless: v = 0.2, 0.4, 0.6, x3 = 0.12.
  EXPECT_NEAR(slide_distance(2.0, 0.0, 0.1, 3), 0.12, 1e-15);
}

TEST(ObstaclesTheory, SlideTendsToTheTerminalSpeed) {
  EXPECT_DOUBLE_EQ(slide_terminal_speed(2.0, 0.5, 0.1), 0.4);
  EXPECT_TRUE(std::isinf(slide_terminal_speed(2.0, 0.0, 0.1)));
  // After many steps each step adds the terminal speed times h.
  const double step = slide_distance(2.0, 0.5, 0.1, 201) - slide_distance(2.0, 0.5, 0.1, 200);
  EXPECT_NEAR(step, 0.4 * 0.1, 1e-12);
}

}  // namespace tecido::suites::obstacles
