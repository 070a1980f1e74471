#pragma once
// Planted benchmark rows for the bench suite's tests (test_bench_report, test_figures): figures
// chosen so that every ratio and range the suite derives from them can be counted by hand.
#include "comparisons/suites/bench/figures.h"

#include <string>
#include <vector>

namespace tecido::suites::bench {

inline BenchRow row(const std::string& name, double ns, double springs = 0, const std::string& label = "") {
  BenchRow r;
  r.name = name;
  r.ns_per_iter = ns;
  r.label = label;
  if (springs > 0) r.counters["springs"] = springs;
  return r;
}

/// Two cloth sizes: core 2 and 6 ns per spring, Bullet 50 and 100 ns per link; tri-tri core 40, fcl 160, exact 80 ns.
inline std::vector<BenchRow> planted() {
  return {row("BM_TriTri/core", 40), row("BM_TriTri/fcl", 160), row("BM_TriTri/exact", 80),
          row("BM_SelfCollision/core/256", 12e6), row("BM_SelfCollision/fcl/256", 2e9),
          row("BM_ClothStep/core-symplectic/16", 2000, 1000, "avx"), row("BM_ClothStep/bullet-classic/16", 50000, 1000),
          row("BM_ClothStep/core-symplectic/32", 24000, 4000, "avx"), row("BM_ClothStep/bullet-classic/32", 400000, 4000)};
}

inline Settings two_sizes() {
  Settings s;
  s.cloth_sizes = {16, 32};
  return s;
}

}  // namespace tecido::suites::bench
