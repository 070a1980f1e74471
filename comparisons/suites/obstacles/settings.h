#pragma once
/// What the `obstacles` suite runs (its own settings; data/tolerances.json holds only the bands of
/// its checks, section "obstacles"). Changing these changes the work done, so they live here, next
/// to the code, and the report prints them.
#include <array>

namespace tecido::suites::obstacles {

struct Settings {
  double g = 9.81;  ///< gravity [m/s^2], along -z

  // Particle dropped on a sphere (midpoint integrator: exact for constant acceleration).
  double sphere_radius = 0.5;   ///< [m], centred at the origin
  double drop_height = 1.0;     ///< start height above the sphere's top [m]
  double drop_elasticity = 0.8; ///< the particle's k: rebound apex k^2 h
  double drop_dt = 1e-3;        ///< [s]

  // Sliding down the +z face of a box tilted by slide_angle about y, with friction (symplectic
  // Euler, the seed's integrator; the seed's friction law: v_t scaled by (1 - mu) once per step).
  double slide_angle = 0.5235987755982988;  ///< 30 degrees [rad]
  double slide_friction = 0.1;              ///< mu of the box
  double slide_dt = 5e-3;                   ///< [s]; a h > the tangential threshold below
  double slide_seconds = 1.0;
  /// The contact thresholds of the slide scene: landing is static and v_t is never zeroed, so the
  /// closed form of the friction law applies from the first step.
  double slide_static_threshold = 1.0, slide_tangential_threshold = 1e-9;
  double slide_start_gap = 1e-9;  ///< start this far above the face [m]

  // Resting on the sphere's top and on the box's top face.
  long long rest_steps = 100000;  ///< 1e4 with --quick
  double rest_dt = 1e-3;

  // Fast particles and huge steps against a thin box and moving bodies (no gravity).
  std::array<double, 5> fast_steps = {1e-3, 1e-2, 0.1, 1.0, 10.0};  ///< [s]
  double fast_speed = 1000.0;         ///< particle speed towards the thin box [m/s]
  double thin_half_thickness = 1e-3;  ///< [m]
  double moving_speed = 50.0;         ///< moving sphere and box [m/s]
  double spin_rate = 20.0;            ///< rotating box [rad/s]
  long long fast_run_steps = 200;     ///< steps per fast case

  // The seed's block (figs 10-13) and the cloth on a sphere: the scenes a user runs, from
  // data/scenes (their choices are documented beside them); the suite only picks the duration.
  std::array<int, 2> block_sides = {11, 22};  ///< 121 and 484 particles
  std::array<const char*, 2> block_files = {"seed_fig10_12_block_121.json", "seed_fig11_13_block_484.json"};
  const char* sphere_file = "cloth_on_sphere.json";
  double block_seconds = 0.0;  ///< 0: each scene's own steps x dt (3 s); 0.6 s with --quick
  int block_frames = 30;       ///< frames counted (equal intervals over the run)
  /// A spring passes through the block's interior when some point of it is deeper than this below
  /// every face (round-off of particles held on a face is not a cut) [m].
  double through_depth = 1e-9;

  // Bullet's classic soft body on the same scenes (reference build).
  double bullet_margin = 1e-3;  ///< the soft body's collision margin [m]
  double bullet_voxel = 0.05;   ///< sparse SDF cell [m] (Bullet's default 0.25 rounds the block's edges more)
};

inline Settings settings(bool quick) {
  Settings s;
  if (quick) {
    s.rest_steps = 10000;
    s.block_seconds = 0.6;
    s.block_frames = 12;
  }
  return s;
}

}  // namespace tecido::suites::obstacles
