// The bench suite's report (comparisons/suites/bench/bench_report.*): goals met and not met, and
// the figures table, computed from planted rows whose figures are counted by hand.
#include "comparisons/suites/bench/bench_report.h"

#include <gtest/gtest.h>

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

TEST(BenchReport, GoalsMetAndNotMetAreCountedFromTheRun) {
  const Figures f = derive_figures(planted(), {}, two_sizes());
  const std::string md = goals_markdown(f, planted(), two_sizes(), Goals{});
  // Met: 0.25 <= 0.5, 0.5 <= 1, 0.04 and 0.06 <= 0.25, 2 <= 3 ns. Not met: 12 > 10 ms, 6 > 3 ns.
  EXPECT_NE(md.find("In this run 5 of the 7 measured goals were met; not met: self-collision 256x256 frame, core, one "
                    "thread; cloth step 32x32: core ns per spring."),
            std::string::npos)
      << md;
  const std::string fig = figures_markdown(f, two_sizes());
  EXPECT_NE(fig.find("| 0.04-0.06x |"), std::string::npos) << fig;
  EXPECT_NE(fig.find("| 2-6 ns |"), std::string::npos) << fig;
  EXPECT_NE(fig.find("12 ms (–; 2000 ms)"), std::string::npos) << fig;
  EXPECT_NE(fig.find("the same without AVX (kernel ?) | – |"), std::string::npos) << "no SSE2 run: no figure";
}

}  // namespace
}  // namespace tecido::suites::bench
