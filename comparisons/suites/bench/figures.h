#pragma once
/// The figures the `bench` suite reports (and docs/benchmarks.md quotes from it), derived from the rows of
/// one run of tecido-bench and of its second, SSE2-only run.
#include "comparisons/suites/bench/benchmark_json.h"
#include "comparisons/suites/bench/settings.h"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace tecido::suites::bench {

/// The smallest and largest of some values; NaN when there were none.
struct Span {
  double lo = NAN, hi = NAN;
  int count = 0;
  /// Adds v (a NaN is ignored).
  void add(double v);
};

struct Figures {
  std::vector<std::pair<std::string, double>> tritri_ns;  ///< BM_TriTri/<engine>: engine, ns per random pair
  double tritri_core_vs_fcl = NAN, tritri_core_vs_exact = NAN;  ///< time ratios
  double selfcollision_ms = NAN, selfcollision_flat_ms = NAN, selfcollision_fcl_ms = NAN;  ///< 256 x 256 frame
  Span cloth_vs_bullet;     ///< core symplectic step time / Bullet classic's, over Settings::cloth_sizes
  Span ns_per_spring;       ///< core symplectic step per spring, over the same sizes
  Span bullet_ns_per_link;  ///< Bullet classic step per link
  Span sse2_ns_per_spring;  ///< core symplectic step per spring in the SSE2-only run
  std::string kernel, sse2_kernel;  ///< the spring kernel each run's core steps report using
};

/// The figures of `rows` (the main run) and `sse2_rows` (the TECIDO_SIMD=sse2 run; may be empty).
Figures derive_figures(const std::vector<BenchRow>& rows, const std::vector<BenchRow>& sse2_rows, const Settings& s);

}  // namespace tecido::suites::bench
