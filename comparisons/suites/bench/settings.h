#pragma once
/// What the `bench` suite runs and the speed goals its report compares with. Goals are targets the
/// project set itself (its issue on speed versus accuracy), not tolerances: timings on a shared
/// machine are reported, never checked, so none of this is in the tolerance file.
#include <string>
#include <vector>

namespace tecido::suites::bench {

struct Settings {
  double min_time = 0.2;  ///< --benchmark_min_time per benchmark [s] (0.01 with --quick)
  std::vector<int> cloth_sizes = {16, 32, 64, 128};  ///< n of the n x n cloths the goal rows and figures cover
  /// The second run: these benchmarks again with TECIDO_SIMD=sse2 (core/platform/simd_level.h), the
  /// spring kernel of a CPU without AVX.
  std::string sse2_filter = "BM_ClothStep/core-symplectic/";
  /// The first run's filter: every benchmark but the 1000-step long run of the 128 x 128 fold
  /// (minutes of its own; `tecido-bench --benchmark_filter=BM_SelfCollisionLongRun/fold128`).
  std::string main_filter = "-BM_SelfCollisionLongRun/fold128";
};

inline Settings settings(bool quick) {
  Settings s;
  if (quick) s.min_time = 0.01;
  return s;
}

/// The project's speed goals.
struct Goals {
  double tritri_vs_fcl = 0.5;          ///< core's tri-tri time at most this fraction of FCL's
  double tritri_vs_exact = 1.0;        ///< ... and of CGAL's exact test
  double selfcollision_256_ms = 10.0;  ///< a folded 256 x 256 cloth frame, core, one thread [ms]
  double cloth_vs_bullet = 0.25;       ///< core symplectic step time / Bullet classic's
  double ns_per_spring = 3.0;          ///< core's cloth step per spring [ns]
};

}  // namespace tecido::suites::bench
