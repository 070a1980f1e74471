#pragma once
/// Bullet's two cloth engines as entries of the dynamics registry (dynamics_engines.h), built on
/// the reference adapters (reference/bullet_deformable.h, reference/bullet_softbody.h) behind
/// bullet_dynamics.h:
/// - "bullet-deformable": the deformable world in explicit mode, a like-for-like twin of core's
///   symplectic Euler (same model: Hooke springs, masses, pins). Its solver iteration caps do not
///   change an undamped explicit step (the mass-preconditioned linear solve converges in one
///   iteration), so it is one entry, not one per iteration count.
/// - "bullet-deformable-implicit-itK": the same world in implicit mode (Newton on a linearised
///   backward-Euler step, Bullet's default 5 Newton iterations), with the conjugate-gradient solve
///   capped at K iterations: the deformable world's real iteration knob.
/// - "bullet-classic-itK": the classic, position-based soft body with K position-solver sweeps
///   (kDP = 0: the registry's scenes are undamped). Its links are constraints, not springs: kLST
///   is calibrated per scene, step and K so that the static sag matches core's (classic_klst.h).
#include "comparisons/engines/classic_calibration.h"
#include "comparisons/engines/dynamics_entry.h"

#include <vector>

namespace tecido::engines {

/// Bullet's engines in order: the explicit deformable twin, the implicit deformable world at 1, 4
/// and 16 CG iterations, the classic soft body at 1, 4 and 16 position sweeps, its kLST
/// calibrated with `classic`'s rules.
std::vector<DynamicsEntry> bullet_dynamics_entries(const ClassicCalibration& classic);

}  // namespace tecido::engines
