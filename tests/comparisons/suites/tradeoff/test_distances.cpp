// Distances between position sets (comparisons/suites/tradeoff/distances.h), hand-worked. (A copy
// of the Distances test of tests/comparisons/suites/test_stability_suite.cpp, whose old copy is to
// be deleted at integration.)
#include "comparisons/suites/tradeoff/distances.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tecido::suites::tradeoff {
namespace {

TEST(TradeoffDistances, RmsAndMaxAbs) {
  const std::vector<Vec3> a = {Vec3(0, 0, 0), Vec3(1, 1, 1)};
  const std::vector<Vec3> b = {Vec3(3, 4, 0), Vec3(1, 1, 1)};
  EXPECT_DOUBLE_EQ(rms_distance(a, b), std::sqrt(25.0 / 2.0));
  EXPECT_DOUBLE_EQ(max_abs_difference(a, b), 4.0);
  EXPECT_EQ(max_abs_difference(a, a), 0.0);
  std::vector<Vec3> c = a;
  c[1].x() = std::nan("");
  EXPECT_EQ(max_abs_difference(a, c), std::numeric_limits<double>::infinity());
}

TEST(TradeoffDistances, MismatchedOrEmptySets) {
  const std::vector<Vec3> a = {Vec3(0, 0, 0)}, b = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  EXPECT_TRUE(std::isnan(rms_distance(a, b)));
  EXPECT_TRUE(std::isnan(rms_distance({}, {})));
  EXPECT_EQ(max_abs_difference(a, b), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace tecido::suites::tradeoff
