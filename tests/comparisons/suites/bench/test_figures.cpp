// The bench suite's figures (comparisons/suites/bench/figures.*) on planted rows whose ratios and
// ranges are counted by hand.
#include "comparisons/suites/bench/figures.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::suites::bench {
namespace {

BenchRow row(const std::string& name, double ns, double springs = 0, const std::string& label = "") {
  BenchRow r;
  r.name = name;
  r.ns_per_iter = ns;
  r.label = label;
  if (springs > 0) r.counters["springs"] = springs;
  return r;
}

/// Two cloth sizes: core 2 and 6 ns per spring, Bullet 50 and 100 ns per link; tri-tri core 40, fcl 160, exact 80 ns.
std::vector<BenchRow> planted() {
  return {row("BM_TriTri/core", 40), row("BM_TriTri/fcl", 160), row("BM_TriTri/exact", 80),
          row("BM_SelfCollision/core/256", 12e6), row("BM_SelfCollision/fcl/256", 2e9),
          row("BM_ClothStep/core-symplectic/16", 2000, 1000, "avx"), row("BM_ClothStep/bullet-classic/16", 50000, 1000),
          row("BM_ClothStep/core-symplectic/32", 24000, 4000, "avx"), row("BM_ClothStep/bullet-classic/32", 400000, 4000)};
}

Settings two_sizes() {
  Settings s;
  s.cloth_sizes = {16, 32};
  return s;
}

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
