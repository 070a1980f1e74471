// core/dynamics/random_wind.h: the seed's random wind heading. Asserted against the model's own
// definition (a uniform start, a random walk of independent N(0, D tau) knot steps, linear between
// knots) through its statistics on planted seeds, and the promise that a value depends only on
// (seed, D, tau, t): not on the table's length nor on the order of evaluation.
#include "core/dynamics/random_wind.h"
#include "core/dynamics/wind.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace tecido {
namespace {

RandomHeading heading(std::uint64_t seed, double d, double tau, double horizon) {
  RandomHeading h;
  h.seed = seed;
  h.diffusion = d;
  h.knot_interval = tau;
  h.prepare(horizon);
  return h;
}

TEST(RandomWind, ValuesDependOnlyOnSeedAndTimeNotOnTheTable) {
  const RandomHeading short_table = heading(7, 0.3, 0.1, 1.0), long_table = heading(7, 0.3, 0.1, 20.0);
  RandomHeading none = short_table;
  none.knots.clear();
  for (double t : {0.0, 0.05, 0.1, 0.95, 1.0, 1.37, 5.0, 12.34, 19.99}) {
    EXPECT_EQ(short_table.offset(t), long_table.offset(t)) << t;  // bit for bit
    EXPECT_EQ(none.offset(t), long_table.offset(t)) << t;
  }
  // Evaluating in another order gives the same values (no hidden state).
  EXPECT_EQ(long_table.offset(3.3), heading(7, 0.3, 0.1, 20.0).offset(3.3));
  EXPECT_NE(heading(8, 0.3, 0.1, 1.0).offset(0.5), short_table.offset(0.5));
}

TEST(RandomWind, LinearBetweenKnotsAndStartInRange) {
  const RandomHeading h = heading(3, 0.5, 0.2, 4.0);
  EXPECT_EQ(h.offset(0.0), h.knots[0]);
  EXPECT_EQ(h.offset(-1.0), h.knots[0]);
  EXPECT_GE(h.knots[0], 0.0);
  EXPECT_LT(h.knots[0], 2.0 * M_PI);
  EXPECT_NEAR(h.offset(0.2 * 5 + 0.1), 0.5 * (h.knots[5] + h.knots[6]), 1e-12);
  EXPECT_NEAR(h.offset(0.2 * 5 + 0.05), 0.75 * h.knots[5] + 0.25 * h.knots[6], 1e-12);
  // No diffusion: only the random start remains.
  const RandomHeading still = heading(3, 0.0, 0.2, 4.0);
  EXPECT_EQ(still.offset(3.9), still.knots[0]);
  EXPECT_EQ(still.knots[0], h.knots[0]);
}

TEST(RandomWind, StepsAreIndependentNormalsOfVarianceDTau) {
  const double d = 0.4, tau = 0.05;
  const int n = 200000;
  double sum = 0.0, sq = 0.0, lag = 0.0, prev = 0.0;
  for (int k = 1; k <= n; ++k) {
    const double x = random_heading_step(11, d, tau, static_cast<std::uint64_t>(k));
    sum += x;
    sq += x * x;
    lag += x * prev;
    prev = x;
  }
  const double var = d * tau, mean = sum / n;
  EXPECT_NEAR(mean, 0.0, 5.0 * std::sqrt(var / n));
  EXPECT_NEAR(sq / n / var, 1.0, 0.02);    // the variance, within ~6 standard errors
  EXPECT_NEAR(lag / n / var, 0.0, 0.02);   // no lag-1 correlation
}

TEST(RandomWind, WalkSpreadsAsDiffusionOverSeeds) {
  // Var(W(t)) = D t for a walk with N(0, D tau) steps; uniform starts have mean pi.
  const double d = 0.1, t = 10.0;
  const int seeds = 4000;
  double sum = 0.0, sq = 0.0, start = 0.0;
  for (int s = 0; s < seeds; ++s) {
    const RandomHeading h = heading(1000 + s, d, 0.1, t);
    const double w = h.offset(t) - h.knots[0];
    sum += w;
    sq += w * w;
    start += h.knots[0];
  }
  EXPECT_NEAR(sum / seeds, 0.0, 5.0 * std::sqrt(d * t / seeds));
  EXPECT_NEAR(sq / seeds / (d * t), 1.0, 0.1);  // ~4.5 standard errors of a variance from 4000 draws
  EXPECT_NEAR(start / seeds, M_PI, 5.0 * M_PI / std::sqrt(3.0 * seeds));
}

TEST(RandomWind, WindKeepsItsMagnitudeAndTurnsAboutItsAxis) {
  Wind w;
  w.force = Vec3(0.1, 0, 0);
  w.swirl = true;
  w.axis = Vec3(0, 1, 0);
  w.rate = 0.7;
  w.random = std::make_shared<const RandomHeading>(heading(5, 0.2, 0.1, 10.0));
  for (double t : {0.0, 1.3, 4.44, 9.9}) {
    const Vec3 f = w.at(t);
    EXPECT_NEAR(f.norm(), 0.1, 1e-15);
    EXPECT_NEAR(f.y(), 0.0, 1e-15);
    const double th = 0.7 * t + w.random->offset(t);  // e1 = +x, e2 = axis x e1 = -z
    EXPECT_NEAR(f.x(), 0.1 * std::cos(th), 1e-14);
    EXPECT_NEAR(f.z(), -0.1 * std::sin(th), 1e-14);
  }
}

}  // namespace
}  // namespace tecido
