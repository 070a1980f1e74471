#pragma once
/// What the `stability` suite runs: its own settings, next to its code and printed in its report.
/// The tolerance file holds only the bands its checks use (/stability/...), so editing that file
/// changes pass or fail, never what runs or for how long; changing a number here changes the work.
#include "core/dynamics/integrator.h"

#include <vector>

namespace tecido::suites::stability {

/// Coordinates offset by large amounts: every run is compared with the same run at the origin.
struct OffsetSettings {
  std::vector<double> offsets = {1e6, 1e7, 1e8};  ///< added to every coordinate [m]
  /// Oscillators (symplectic, ks = 4 N/m, m = 1 kg, so omega = 2 1/s): rest length and initial
  /// stretch [m] of each, run for `periods` periods at step `dt`.
  struct Spring {
    double rest_length, amplitude;
  };
  std::vector<Spring> springs = {{1.0, 0.1}, {0.01, 1e-3}};
  double stiffness = 4.0, mass = 1.0;
  double dt = 1e-3;          ///< [s]
  double periods = 10.0;
  long long drop_steps = 3000;  ///< a particle dropped 1 m on a plane, at dt, for this many steps
};

/// Mass ratios across a spring: the largest stable step of a free pair and of an anchored chain
/// (by the same bisection and definition of "stable at h" as the grid), against omega_max.
struct MassRatioSettings {
  double stiffness = 1.0;   ///< [N/m]
  double heavy = 1.0;       ///< [kg]
  double light = 1e-6;      ///< [kg]: the ratio is heavy / light
};

/// Springs of near-zero rest length.
struct NearZeroSettings {
  std::vector<double> rest_lengths = {1e-9, 1e-12, 1e-15};  ///< [m]
  double amplitude = 1e-3;        ///< oscillating through the anchor (ks = 1 N/m, m = 1 kg) [m]
  double beside = 1e-12;          ///< the second pass runs this far beside the anchor [m]
  double dt = 0.01;               ///< [s]
  double periods = 20.0;
  long long coincident_steps = 1000;  ///< runs of a spring whose two ends coincide
  std::vector<double> separations = {1e-160, 1e-200};  ///< ends this far apart: |d|^2 subnormal, then 0 [m]
  double tiny_rest_length = 1e-15;  ///< rest length of the spring at those separations [m]
};

/// A particle resting on a plane under gravity.
struct RestingSettings {
  long long steps = 100000;
  double dt = 0.01;       ///< [s]
  double offset = 1e6;    ///< the symplectic run is repeated with the scene shifted this far [m]
};

/// A particle falling onto a thin bounded plane with very long steps.
struct TunnellingSettings {
  std::vector<double> speeds = {1.0, 1000.0};         ///< initial downward speed [m/s]
  std::vector<double> dts = {1e-3, 1e-2, 0.1, 1.0, 10.0};  ///< [s]
  double duration = 20.0;  ///< simulated time [s] (at least `min_steps` steps)
  long long min_steps = 20;
};

/// Outside dynamics engines (--plugin, --engine-cmd): the largest stable step of the same
/// oscillator on the quick grid's cells, by the same bisection. Their runs are shorter (a process
/// engine pays a round trip per period) and "stable at h" is checked once per period.
struct OutsideSettings {
  double periods = 100.0;  ///< per run (the amplitude bound is the suite's)
  int max_halvings = 8;    ///< no stable step down to 2^-8 / omega: reported as none
  std::vector<double> stiffnesses = {1e-2, 1e1, 1e4};
  std::vector<double> masses = {1e-3, 1e0, 1e3};
};

struct Settings {
  /// "Stable at h": a run of `periods` periods (2 pi / omega each) at step h stays finite and its
  /// displacement from equilibrium never exceeds `amplitude_bound` times the initial one.
  double periods = 1000.0;
  double amplitude_bound = 1000.0;
  /// The bisection on h stops when its bracket is rel_tol * h wide. Starting at h = 1/omega it
  /// doubles at most max_doublings times or halves at most max_halvings times to bracket the limit;
  /// finding nothing stable down to 2^-max_halvings / omega it reports "no stable step" (which
  /// bounds the work: a run there is 2^max_halvings times longer than one at 1/omega).
  double rel_tol = 1e-6;
  int max_doublings = 20;
  int max_halvings = 12;

  /// The grid of the largest-stable-step table [N/m] x [kg] (3 x 3 with --quick, 7 x 7 without).
  std::vector<double> stiffnesses, masses;
  /// Integrators with a stable step (measured on the grid) and without one (growth and horizons).
  std::vector<IntegratorKind> bounded = {IntegratorKind::Symplectic, IntegratorKind::RK4};
  std::vector<IntegratorKind> growers = {IntegratorKind::Euler, IntegratorKind::Midpoint};

  /// Growth per period of the growers: one run of growth_periods periods at h = c / omega for each
  /// c and grid cell.
  std::vector<double> growth_cs = {0.01, 0.1, 1.0};
  double growth_periods = 20.0;

  /// The growers' "largest stable step" over N periods (ks = 1 N/m, m = 1 kg), for each N here
  /// (10, 30, 100 with --quick; also 300 without), bisected to horizon_rel_tol.
  std::vector<double> horizons;
  double horizon_rel_tol = 1e-4;

  OffsetSettings offset;
  MassRatioSettings mass_ratio;
  NearZeroSettings near_zero;
  RestingSettings resting;
  TunnellingSettings tunnelling;
  OutsideSettings outside;
};

/// The suite's settings, the smaller grid and fewer horizons with --quick (the checks are the same).
inline Settings settings(bool quick) {
  Settings s;
  s.stiffnesses = quick ? std::vector<double>{1e-2, 1e1, 1e4} : std::vector<double>{1e-2, 1e-1, 1e0, 1e1, 1e2, 1e3, 1e4};
  s.masses = quick ? std::vector<double>{1e-3, 1e0, 1e3} : std::vector<double>{1e-3, 1e-2, 1e-1, 1e0, 1e1, 1e2, 1e3};
  s.horizons = quick ? std::vector<double>{10, 30, 100} : std::vector<double>{10, 30, 100, 300};
  return s;
}

}  // namespace tecido::suites::stability
