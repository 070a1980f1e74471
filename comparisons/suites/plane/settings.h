#pragma once
/// What the `plane` suite runs: its own settings, next to its code and printed in its report. The
/// tolerance file holds only the bands of its checks (/plane/...), so editing that file changes pass
/// or fail, never what runs; changing a number here changes the work.
#include "core/dynamics/integrator.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tecido::suites::plane {

/// Contact time by bisection (seed fig. 8): particles dropped on a large floor under gravity; the
/// first contact's time from core's contact log against the analytic root, for each integrator x
/// step h x bisection tolerance h 2^-level. Drop d's inputs come from substream(seed, first_stream + d),
/// the same drops in every cell.
struct ContactTimeSettings {
  std::vector<IntegratorKind> integrators = {IntegratorKind::Midpoint, IntegratorKind::Symplectic};
  std::vector<double> steps = {0.1, 0.02, 0.005};         ///< h [s]
  std::vector<int> levels = {4, 8, 12, 16, 20, 24, 28};   ///< bisection tolerance h 2^-level
  int drops = 100;                                        ///< per cell (20 with --quick)
  double height_lo = 0.2, height_hi = 5.0;                ///< initial height z0, uniform [m]
  double vz_lo = -3.0, vz_hi = 3.0;                       ///< initial vertical speed, uniform [m/s]
  double v_horizontal = 1.0;                              ///< each horizontal component uniform in [-v, v] [m/s]
  double gravity = 9.81;                                  ///< [m/s^2], along -z
  double elasticity = 0.5, mass = 1.0;
  double floor_half_extent = 100.0;                       ///< the floor z = 0 is a square of this half side [m]
  double max_time = 10.0;                                 ///< a drop with no contact by then is missing [s]
  std::uint64_t first_stream = 777000;
};

/// The same drop in core and in Bullet: a particle (core; Bullet's deformable twin, one node) and a
/// small rigid sphere (Bullet) released at rest at each height, run until `into_fall` of the first
/// rebound's flight after the analytic contact time.
struct DropSettings {
  std::vector<double> heights = {0.2, 1.0, 3.0};  ///< z0 [m]
  double dt = 0.005;                              ///< [s]; core integrates with midpoint
  double gravity = 9.81;                          ///< [m/s^2]
  double elasticity = 0.5;                        ///< k: the rebound speed is k times the impact speed
  double sphere_radius = 1e-3;                    ///< Bullet's rigid sphere [m]
  double floor_half_extent = 10.0;                ///< [m]
  double into_fall = 0.75;                        ///< fraction of the first rebound's flight
  double node_slack = 1e-6;                       ///< Bullet's node touches within its margin + this [m]
};

struct Settings {
  long random_cases = 10000;         ///< of the `random` category (2000 with --quick)
  long cases_per_category = 2000;    ///< of each adversarial category (250 with --quick)
  long block = 1000;                 ///< cases per sweep case: one block of one category
  std::size_t max_disagreements = 100000;  ///< kept in the disagreement file (engine, category, case order)
  ContactTimeSettings contact_time;
  DropSettings drop;
};

/// The suite's settings; --quick runs fewer cases and drops (the checks are the same).
inline Settings settings(bool quick) {
  Settings s;
  if (quick) {
    s.random_cases = 2000;
    s.cases_per_category = 250;
    s.contact_time.drops = 20;
  }
  return s;
}

}  // namespace tecido::suites::plane
