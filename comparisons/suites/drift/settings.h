#pragma once
/// What the `drift` suite runs: its own settings (the tolerance file holds only the bands of its
/// checks, /drift/...). Changing these changes the work done, so they live here, next to the code,
/// and the report prints them.
namespace tecido::suites::drift {

struct Settings {
  // (a) Invariants of core's four integrators on conservative scenes (scenes.h).
  long long steps = 100000;  ///< steps per run (20000 with --quick)
  int sample_every = 100;    ///< energy, momentum and angular momentum are sampled every this many steps
  int plot_every = 1000;     ///< the energy plot's data file gets a point every this many steps

  // (b) Core versus Bullet's deformable twin: an undamped, square cloth pinned at two corners.
  int twin_nodes = 11;              ///< nodes per side
  double twin_spacing = 0.1;        ///< [m]
  double twin_mass = 1.0;           ///< [kg]
  double twin_stiffness = 100.0;    ///< type B springs [N/m] (no type A)
  double twin_dt = 1.0 / 240.0;     ///< [s]
  double twin_seconds = 5.0;        ///< run length [s] (3 with --quick)
  double twin_window = 1.0;         ///< the round-off check takes the largest RMS distance over [0, window] [s]
  double twin_thresholds[3] = {1e-9, 1e-6, 1e-3};  ///< RMS distances whose first crossing times are reported [m]

  // The same cloth released flat above a floor (k = 0).
  double fall_height = 0.5;   ///< [m]
  double fall_seconds = 1.0;  ///< [s]

  // (c) The classic soft body: kLST calibrated on a curtain hung from its top row, then run at
  // another load (every mass times load_factor), which it was not calibrated on.
  int classic_nodes = 6;            ///< nodes per side
  double classic_side = 0.3;        ///< [m]
  double classic_mass = 0.1;        ///< [kg]
  double classic_stiffness = 100.0; ///< type B springs [N/m]
  double classic_dt = 1e-3;         ///< [s]
  double classic_load_factor = 2.0; ///< the validation load, as a multiple of the calibration's
  int classic_piterations = 10;     ///< position sweeps per step
  double classic_kdp = 0.05;        ///< Bullet's velocity damping while settling
  double classic_rest_speed = 1e-6; ///< settled when every node is slower than this [m/s]
  double classic_max_time = 60.0;   ///< a settle gives up after this much simulated time [s]
  /// The calibrator's stopping rule: it stops when the sags match within this fraction. A setting
  /// (it decides how long the calibration runs), not a band.
  double classic_calibration_tolerance = 1e-3;
};

inline Settings settings(bool quick) {
  Settings s;
  if (quick) {
    s.steps = 20000;
    s.twin_seconds = 3.0;
  }
  return s;
}

}  // namespace tecido::suites::drift
