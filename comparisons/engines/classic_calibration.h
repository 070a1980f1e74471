#pragma once
/// How the classic soft body's kLST is calibrated for each (cloth, step, sweeps) it runs at
/// (reference/klst_calibration.h): settling damping at a fixed rate, a rest speed, a sag match
/// and a time limit. A 1 % sag match (2.5 mm on the 16^2 curtain's 0.25 m) is far inside the
/// classic body's dynamic mismatch with the spring cloth.

namespace tecido::engines {

struct ClassicCalibration {
  double kdp_rate = 6.4;             ///< kDP = min(0.5, kdp_rate h) while settling [1/s]
  double rest_speed = 1e-4;          ///< [m/s]
  double relative_tolerance = 1e-2;  ///< the calibrator's stopping rule
  double max_time = 30.0;            ///< simulated time per settle at most [s]
};

}  // namespace tecido::engines
