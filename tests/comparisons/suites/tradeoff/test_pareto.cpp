// The Pareto front (comparisons/suites/tradeoff/pareto.h) on planted sets whose fronts are worked
// out by hand. (A copy of the ParetoFront test of tests/comparisons/suites/test_stability_suite.cpp,
// whose old copy is to be deleted at integration, plus more cases.)
#include "comparisons/suites/tradeoff/pareto.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tecido::suites::tradeoff {
namespace {

TEST(TradeoffParetoFront, PlantedSet) {
  const double nan = std::nan("");
  const std::vector<CostError> pts = {
      {1.0, 10.0},  // 0 front
      {2.0, 5.0},   // 1 front
      {3.0, 5.0},   // 2 dominated by 1 (same error, dearer)
      {2.0, 6.0},   // 3 dominated by 1 (same cost, worse)
      {4.0, 1.0},   // 4 front
      {5.0, 1.0},   // 5 dominated by 4
      {0.5, 20.0},  // 6 front: cheapest
      {nan, 0.1},   // 7 ignored
      {4.0, 1.0},   // 8 equal to 4: both kept
      {6.0, 0.5},   // 9 front: most accurate
      {7.0, 0.5},   // 10 dominated by 9
  };
  const std::vector<int> want = {6, 0, 1, 4, 8, 9};
  EXPECT_EQ(pareto_front(pts), want);
  EXPECT_TRUE(pareto_front({}).empty());
  EXPECT_EQ(pareto_front({{1.0, 1.0}}), std::vector<int>{0});
}

TEST(TradeoffParetoFront, NonFinitePointsNeitherJoinNorDominate) {
  const double inf = std::numeric_limits<double>::infinity();
  // An infinitely cheap point with a NaN error would dominate everything if it counted.
  const std::vector<CostError> pts = {{-inf, std::nan("")}, {1.0, inf}, {2.0, 3.0}, {3.0, 2.0}};
  EXPECT_EQ(pareto_front(pts), (std::vector<int>{2, 3}));
  EXPECT_TRUE(pareto_front({{std::nan(""), 1.0}}).empty());
}

TEST(TradeoffParetoFront, EveryPointOffTheFrontIsDominatedByAFrontPoint) {
  // A planted grid: cost i, error (7 - i) + (i % 3): the front is worked out by hand.
  std::vector<CostError> pts;
  for (int i = 0; i < 7; ++i) pts.push_back({static_cast<double>(i), 7.0 - i + (i % 3)});
  // errors: 7, 7, 7, 4, 4, 4, 1 -> the front is i = 0, 3, 6.
  const std::vector<int> front = pareto_front(pts);
  EXPECT_EQ(front, (std::vector<int>{0, 3, 6}));
  for (int i = 0; i < 7; ++i) {
    if (std::find(front.begin(), front.end(), i) != front.end()) continue;
    bool dominated = false;
    for (int f : front) dominated = dominated || (pts[f].cost <= pts[i].cost && pts[f].error <= pts[i].error);
    EXPECT_TRUE(dominated) << i;
  }
}

}  // namespace
}  // namespace tecido::suites::tradeoff
