#pragma once
/// What the `bench` suite runs and the speed goals its report compares with. Goals are targets the
/// project set itself (its issue on speed versus accuracy), not tolerances: timings on a shared
/// machine are reported, never checked, so none of this is in the tolerance file.
#include <string>
#include <vector>

namespace tecido::suites::bench {

struct Settings {
  double min_time = 0.2;  ///< --benchmark_min_time per benchmark [s] (0.01 with --quick)
  /// Each benchmark of the first run this many times; the report reads their median (1 with
  /// --quick: the one measurement). On a shared virtual machine a single measurement of the
  /// threaded rows moved their speed-ups by 0.4 between two runs of one build.
  int repetitions = 3;
  std::vector<int> cloth_sizes = {16, 32, 64, 128};  ///< n of the n x n cloths the goal rows and figures cover
  /// The second run: these benchmarks again with TECIDO_SIMD=sse2 (core/platform/simd_level.h), the
  /// spring kernel of a CPU without AVX.
  std::string sse2_filter = "BM_ClothStep/core-symplectic/";
  /// The first run's filter: every benchmark but the 1000-step long run of the 128 x 128 fold
  /// (minutes of its own, mostly the simulation's: `tecido-bench --benchmark_filter=BM_SelfCollisionLongRun/fold128`;
  /// its goal rows appear in the report only when its rows are in the run).
  std::string main_filter = "-BM_SelfCollisionLongRun/fold128";
  /// The whole `tecido selfcollide` process (process_cost.h): the n x n fold (2 (n - 1)^2
  /// triangles: 32258 at 128), rounds, and the thread counts of the continuous command.
  int process_n = 128;
  int process_rounds = 3;
  std::vector<int> process_threads = {1, 2};
  /// The size of the continuous-detection and thread goal rows: BM_ContinuousSelfCollision/<...>/n.
  int continuous_n = 128, threads_n = 256;
};

inline Settings settings(bool quick) {
  Settings s;
  if (quick) {
    s.min_time = 0.01;
    s.repetitions = 1;
    s.process_rounds = 1;
  }
  return s;
}

/// The project's speed goals.
struct Goals {
  double tritri_vs_fcl = 0.5;          ///< core's tri-tri time at most this fraction of FCL's
  double tritri_vs_exact = 1.0;        ///< ... and of CGAL's exact test
  double selfcollision_256_ms = 10.0;  ///< a folded 256 x 256 cloth frame, core, one thread [ms]
  double cloth_vs_bullet = 0.25;       ///< core symplectic step time / Bullet classic's
  double ns_per_spring = 3.0;          ///< core's cloth step per spring [ns]
  // Issue 24: continuous self-collision at the speed of discrete, on real meshes and in long runs.
  double selfcollision_flat_256_ms = 15.0;  ///< the flat 256 x 256 frame, core, one thread [ms]
  double continuous_over_discrete = 3.0;    ///< continuous detection of a step / discrete of its end frame
  double ccd_vs_fcl = 0.5;                  ///< core's continuous test time per query / FCL's, on the mix
  double ccd_false_positive_share = 0.01;   ///< core's false positives over the referee's negatives
  double ccd_false_negatives = 0.0;         ///< core's false negatives on the mix (a count)
  double thread_speedup = 1.7;              ///< wall time on 1 thread / on 2 (at least)
  double kept_over_scratch = 1.0;           ///< long run: kept detector's time per step / from scratch
};

}  // namespace tecido::suites::bench
