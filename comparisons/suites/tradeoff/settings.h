#pragma once
/// What the `tradeoff` suite runs: its own settings (the tolerance file holds only the bands of its
/// checks, /tradeoff/...). Changing these changes the work done, which runs count and which points
/// are rerun, so they live here, next to the code, and the report prints them.
#include "comparisons/engines/classic_calibration.h"

#include <vector>

namespace tecido::suites::tradeoff {

/// A cloth size and how many step sizes it sweeps (h0, h0/2, ...).
struct Size {
  int n = 0;      ///< nodes per side
  int steps = 0;  ///< swept step sizes
};

/// How far Bullet's engines are run (their cost grows as nodes x steps; a full sweep up to 128^2
/// and h0/16 would take hours): cloths of at most max_side^2 nodes, at the max_steps largest
/// swept steps only. The points outside are not run (and not listed).
struct BulletRange {
  int max_side_explicit = 32;  ///< bullet-deformable
  int max_side_implicit = 16;  ///< bullet-deformable-implicit-itK (Newton and CG iterations cost most)
  int max_side_classic = 16;   ///< bullet-classic-itK (plus a kLST calibration per point)
  int max_steps = 3;           ///< h0, h0/2, h0/4
};

/// How far outside engines (--plugin, --engine-cmd) are run: cloths of at most max_side^2 nodes,
/// at every swept step (max_steps = 0; explicit methods diverge at the largest ones, so a shorter
/// range could leave an engine without a single point). A process engine in a scripting language
/// steps orders of magnitude slower than core: its run takes minutes even so.
struct OutsideRange {
  int max_side = 16;
  int max_steps = 0;  ///< 0: every swept step
};

/// How the classic soft body's kLST is calibrated (the registry's engine, classic_calibration.h).
using ClassicCalibration = engines::ClassicCalibration;

struct Settings {
  std::vector<Size> sizes = {{16, 5}, {32, 5}, {64, 4}, {128, 2}};  ///< {16, 5}, {32, 4} with --quick
  double seconds = 1.0;      ///< simulated time of every run [s]
  /// A run counts (is on the cost/error plane) when it stays finite and its RMS error to the
  /// reference is at most this [m]; a larger error is listed as unstable. It decides which runs
  /// count and so which points are on the front (and rerun): a setting, not a band.
  double max_error = 0.1;
  double stray_limit = 1e3;  ///< a node this far from its start [m] ends a run as diverged (guarded_run.h)
  double nudge = 1e-12;      ///< the conditioning probes move every free node by this [m]
  int reference_divisor = 4; ///< the reference runs RK4 at h_min / reference_divisor
  /// Timing: a run shorter than timing_min_seconds is repeated (up to timing_max_repeats calls or
  /// timing_max_total seconds in all) and the fastest call is kept.
  double timing_min_seconds = 0.05;
  double timing_max_total = 0.25;
  int timing_max_repeats = 10;
  BulletRange bullet;
  OutsideRange outside;
  ClassicCalibration classic;
};

inline Settings settings(bool quick) {
  Settings s;
  if (quick) s.sizes = {{16, 5}, {32, 4}};
  return s;
}

}  // namespace tecido::suites::tradeoff
