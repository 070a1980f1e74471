// The bench suite's figures (comparisons/suites/bench/figures.*) on planted rows whose ratios and
// ranges are counted by hand.
#include "comparisons/suites/bench/figures.h"

#include "tests/comparisons/suites/bench/planted_rows.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::bench {
namespace {

TEST(BenchFigures, RatiosAndRangesFromTheRows) {
  const std::vector<BenchRow> sse2 = {row("BM_ClothStep/core-symplectic/16", 3000, 1000, "sse2"),
                                      row("BM_ClothStep/core-symplectic/32", 16000, 4000, "sse2")};
  const Figures f = derive_figures(planted(), sse2, two_sizes());
  ASSERT_EQ(f.tritri_ns.size(), 3u);
  EXPECT_EQ(f.tritri_ns[1].first, "fcl");
  EXPECT_DOUBLE_EQ(f.tritri_core_vs_fcl, 0.25);
  EXPECT_DOUBLE_EQ(f.tritri_core_vs_exact, 0.5);
  EXPECT_DOUBLE_EQ(f.selfcollision_ms, 12.0);
  EXPECT_DOUBLE_EQ(f.selfcollision_fcl_ms, 2000.0);
  EXPECT_TRUE(std::isnan(f.selfcollision_flat_ms)) << "no core-flat row";
  EXPECT_DOUBLE_EQ(f.cloth_vs_bullet.lo, 0.04);  // 2000 / 50000
  EXPECT_DOUBLE_EQ(f.cloth_vs_bullet.hi, 0.06);  // 24000 / 400000
  EXPECT_DOUBLE_EQ(f.ns_per_spring.lo, 2.0);
  EXPECT_DOUBLE_EQ(f.ns_per_spring.hi, 6.0);
  EXPECT_DOUBLE_EQ(f.bullet_ns_per_link.lo, 50.0);
  EXPECT_DOUBLE_EQ(f.bullet_ns_per_link.hi, 100.0);
  EXPECT_DOUBLE_EQ(f.sse2_ns_per_spring.lo, 3.0);
  EXPECT_DOUBLE_EQ(f.sse2_ns_per_spring.hi, 4.0);
  EXPECT_EQ(f.kernel, "avx");
  EXPECT_EQ(f.sse2_kernel, "sse2");
  const Figures none = derive_figures({}, {}, two_sizes());
  EXPECT_EQ(none.ns_per_spring.count, 0);
  EXPECT_TRUE(std::isnan(none.tritri_core_vs_fcl));
}

}  // namespace
}  // namespace tecido::suites::bench
