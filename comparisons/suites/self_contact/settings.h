#pragma once
/// What the self-contact experiment runs and the constants of its claim rules, with the --quick
/// variant. Printed in experiment.md and experiment.json; nothing here is fitted to the seed's
/// tables (calibration.h fits the two calibrated parameters, on its own subset of cells).
#include <cstdint>
#include <vector>

namespace tecido::suites::self_contact {

struct Settings {
  double simulated_time = 10.0;  ///< [s] per run: the seed's tables count 501, 1001, 2000 frames
  int seeds = 10;                ///< runs per cell (wind realisations), unless --seeds says otherwise

  /// Claim rules (claims.h), all set before any run was compared. Verdicts at level alpha after
  /// Holm's adjustment within each family of claims.
  double alpha = 0.05;
  /// "Little" / "level": equivalence of a relative effect to 0 within +-margin, the smallest gain
  /// the seed reports as a gain (mode 3's 10% at 0.1 N).
  double margin = 0.10;
  /// "About 20%": equivalence of (ours - the seed's) within +-size_margin: the seed's own statements
  /// of mode 3's gain span 10% to 20% (10% at 0.1 N, 20% at the other winds, "up to 20%").
  double size_margin = 0.10;
  /// cells-match: the rate of seed values outside our 95% prediction intervals is equivalent to 5%
  /// when it lies in [coverage_lo, coverage_hi]: the rates of a 95% interval whose width is off by
  /// a factor of about 4/3 either way (z 1.96 x 4/3 -> 0.9%, z 1.96 x 3/4 -> 14%).
  double coverage_lo = 0.01, coverage_hi = 0.14;
  /// "Much slower": at least this ratio of times (the seed: "extremely low performance").
  double much_slower = 2.0;
  /// "Often" / "constantly": in at least this share of the frames with a contact.
  double majority = 0.5;

  /// Timing cases (timing.h): frames recorded from one run, repetitions of the test over them,
  /// steps of the phase timing and the blocks they are split into (an interval needs >= 2).
  int timing_frames = 8;
  int timing_repeats = 10;
  int phase_steps = 600;
  int phase_blocks = 6;

  /// Calibration (calibration.h): the grid searched, and the step whose no-response cells are fitted.
  std::vector<double> drag_grid{0.0025, 0.005, 0.01, 0.02, 0.04, 0.08};
  std::vector<double> rate_grid{0.25, 0.35, 0.5, 0.7, 1.0, 1.4, 2.0};
  int calibration_step = 1;  ///< index into CellGrid::steps: 0.01 s (100 steps per second)
};

/// Wind seeds: the experiment's runs of seed index s use substream(scene seed, s); the
/// calibration's use substream(scene seed, kCalibrationStream + s), so the fit never sees the
/// realisations it is judged on.
constexpr std::uint64_t kCalibrationStream = 1000000;

inline Settings settings(bool quick) {
  Settings s;
  if (quick) {
    s.simulated_time = 2.0;
    s.seeds = 2;
    s.timing_frames = 2;
    s.timing_repeats = 3;
    s.phase_steps = 90;
    s.phase_blocks = 3;
    s.drag_grid = {0.01, 0.02};
    s.rate_grid = {0.7, 1.4};
  }
  return s;
}

}  // namespace tecido::suites::self_contact
