#pragma once
/// Bullet's two cloth engines as entries of the tradeoff suite (reference build only), built on the
/// reference adapters (reference/bullet_deformable.h, reference/bullet_softbody.h):
/// - "bullet-deformable": the deformable world in explicit mode, a like-for-like twin of core's
///   symplectic Euler (same model: Hooke springs, masses, pins). Its solver iteration caps do not
///   change an undamped explicit step (the mass-preconditioned linear solve converges in one
///   iteration), so it is one entry, not one per iteration count.
/// - "bullet-deformable-implicit-itK": the same world in implicit mode (Newton on a linearised
///   backward-Euler step, Bullet's default 5 Newton iterations), with the conjugate-gradient solve
///   capped at K iterations: the deformable world's real iteration knob.
/// - "bullet-classic-itK": the classic, position-based soft body with K position-solver sweeps
///   (kDP = 0 as the scene is undamped). Its links are constraints, not springs: kLST is calibrated
///   per scene, step and K so that the static sag matches core's (classic_klst), and cached. Its
///   error against the RK4 reference measures the model's mismatch as much as integration error.
#include "comparisons/suites/tradeoff/engines.h"
#include "comparisons/suites/tradeoff/settings.h"

#include <vector>

namespace tecido::suites::tradeoff {

/// The calibrated kLST the classic engine uses for `scene` at step h with `piterations` sweeps:
/// calibrate_klst_for_sag (reference/klst_calibration.h) with the settling and stopping rules of
/// `c`, the secant started from klst_scaling_guess; computed once per (scene, h, piterations,
/// calibration settings) and cached behind a mutex, keyed by a hash of everything it reads. The
/// value is a pure function of its arguments, whatever the order or threads of the calls
/// (concurrent first calls of one key wait for a single computation). Throws what the
/// calibration throws (an engine unstable while settling), every time for that key.
double classic_klst(const Scene& scene, double h, int piterations, const ClassicCalibration& c);

/// Bullet's engines in report order: the explicit deformable twin, the implicit deformable world
/// at 1, 4 and 16 CG iterations, the classic soft body at 1, 4 and 16 position sweeps; each with
/// its range (TradeoffEngine::max_n, max_steps) from s.bullet.
std::vector<TradeoffEngine> bullet_tradeoff_engines(const Settings& s);

}  // namespace tecido::suites::tradeoff
