// The tradeoff suite's formulas (comparisons/suites/tradeoff/theory.h) and its curtain
// (curtain.h): omega_bound hand-worked on a two-spring chain, the swept steps, the step-halving
// estimate on a planted 4th-order error, the observed order, the nudges' size.
#include "comparisons/suites/tradeoff/theory.h"

#include "comparisons/suites/tradeoff/curtain.h"
#include "comparisons/suites/tradeoff/distances.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::tradeoff {
namespace {

TEST(TradeoffTheory, OmegaBoundOfAChain) {
  // 0 -(k=4)- 1 -(k=1)- 2, masses 1, 2, 1: node 1 has 2 (4 + 1) / 2 = 5, node 0 2 * 4 / 1 = 8.
  Scene s;
  s.particles.add(Vec3(0, 0, 0), Vec3::Zero(), 1.0, 0.5, false);
  s.particles.add(Vec3(1, 0, 0), Vec3::Zero(), 2.0, 0.5, false);
  s.particles.add(Vec3(2, 0, 0), Vec3::Zero(), 1.0, 0.5, false);
  s.forces.springs.push_back(Spring{0, 1, 4.0, 1.0, 0.0});
  s.forces.springs.push_back(Spring{1, 2, 1.0, 1.0, 0.0});
  EXPECT_DOUBLE_EQ(omega_bound(s), std::sqrt(8.0));
  // h0 = 2^ceil(log2(2 / sqrt 8)) = 2^ceil(-0.5) = 1.
  EXPECT_EQ(first_step(s), 1.0);
  EXPECT_EQ(swept_steps(s, 3), (std::vector<double>{1.0, 0.5, 0.25}));
}

TEST(TradeoffTheory, StepHalvingRecoversAPlantedFourthOrderError) {
  // e(h) = C h^4 exactly: the distance between runs at h and 2h is e(2h) - e(h) = 15 e(h).
  const double C = 3.0, h = 0.01;
  const double e_h = C * std::pow(h, 4), e_2h = C * std::pow(2 * h, 4);
  EXPECT_NEAR(richardson_error(e_2h - e_h, 4.0), e_h, 1e-15 * e_h);
  EXPECT_NEAR(observed_order(e_2h, e_h), 4.0, 1e-12);
  EXPECT_NEAR(observed_order(1.0, 0.5), 1.0, 1e-15);
}

TEST(TradeoffCurtain, TheSceneAndItsNudges) {
  const Scene s = hanging_cloth(5);
  ASSERT_EQ(s.particles.size(), 25u);
  EXPECT_TRUE(s.particles.pinned[0] && s.particles.pinned[4]);
  EXPECT_NEAR(s.particles.x[24].z(), -1.0, 1e-15);  // 1 m x 1 m, rows down
  for (bool out : {false, true}) {
    const Scene p = nudged(s, 11, out, 1e-12);
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      const Vec3 d = p.particles.x[i] - s.particles.x[i];
      if (s.particles.pinned[i]) {
        EXPECT_EQ(d.norm(), 0.0);
        continue;
      }
      EXPECT_NEAR(d.norm(), 1e-12, 1e-15);  // the coordinates' rounding (ulp 2.2e-16 near 1 m)
      EXPECT_EQ(out ? d.x() : d.y(), 0.0);   // out of the plane along y only; in it, y untouched
    }
    EXPECT_EQ(nudged(s, 11, out, 1e-12).particles.x, p.particles.x);  // seeded
  }
}

}  // namespace
}  // namespace tecido::suites::tradeoff
