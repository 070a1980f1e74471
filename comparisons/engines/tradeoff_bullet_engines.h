#pragma once
/// Bullet's two cloth engines as entries of the tradeoff suite (comparisons/suites/tradeoff_suite.h):
/// each is a TradeoffEngine that simulates the suite's scene for `seconds` at step h and returns
/// the node positions in core's numbering, or nothing when the run became unstable. Built on the
/// reference adapters (reference/bullet_deformable.h, reference/bullet_softbody.h); only defined
/// when the reference build is on (TECIDO_HAVE_REFERENCE), as is every Bullet comparison.
///
/// - "bullet-deformable": the deformable world in explicit mode, a like-for-like twin of core's
///   symplectic Euler (same model: Hooke springs, masses, pins). Its solver iteration caps do not
///   change an undamped explicit step (the mass-preconditioned linear solve converges in one
///   iteration), so it is one entry, not one per iteration count.
/// - "bullet-deformable-implicit-itK": the same world in implicit mode (Newton on a linearised
///   backward-Euler step, Bullet's default 5 Newton iterations), with the conjugate-gradient solve
///   capped at K iterations: the deformable world's real iteration knob.
/// - "bullet-classic-itK": the classic, position-based soft body with K position-solver sweeps
///   (m_cfg.piterations; viterations stay 0, Bullet's default, kDP = 0 as the scene is undamped).
///   Its links are constraints, not springs: kLST is calibrated per scene, step and K so that the
///   static sag matches core's (calibrate_klst_for_sag), and cached (see classic_klst). Its error
///   against the RK4 reference measures the model's mismatch as much as integration error.
#include "comparisons/suites/tradeoff_suite.h"

#include <vector>

namespace tecido::suites {

/// The deformable world's explicit twin of symplectic Euler, "bullet-deformable".
TradeoffEngine bullet_deformable_tradeoff_engine();

/// The deformable world in implicit mode with each linear solve capped at `cg_iterations`
/// conjugate-gradient iterations, "bullet-deformable-implicit-it<cg_iterations>".
TradeoffEngine bullet_deformable_implicit_tradeoff_engine(int cg_iterations);

/// The classic soft body with `piterations` position sweeps per step and kLST calibrated to core's
/// static sag for each (scene, h), "bullet-classic-it<piterations>".
TradeoffEngine bullet_classic_tradeoff_engine(int piterations);

/// The calibrated kLST the classic engine uses for `scene` at step h with `piterations` sweeps:
/// calibrate_klst_for_sag (settling damping kDP = 6.4 h, i.e. 6.4 /s; rest below 1e-4 m/s; sag
/// matched within 1 %; at most 30 s simulated per settle; secant started from an h^2 / piterations
/// scaling law), computed once per (scene, h, piterations) and cached behind a mutex, keyed by a
/// hash of the scene's particles, springs and gravity. Deterministic: the value is a pure function
/// of its arguments, whatever the order or threads of the calls (concurrent first calls of one key
/// wait for a single computation). Throws what the calibration throws (an engine unstable while
/// settling), every time for that key.
double classic_klst(const Scene& scene, double h, int piterations);

/// Every Bullet engine the tradeoff suite compares, in report order: the explicit deformable twin,
/// the implicit deformable world at 1, 4 and 16 CG iterations, the classic soft body at 1, 4 and 16
/// position sweeps.
std::vector<TradeoffEngine> bullet_tradeoff_engines();

}  // namespace tecido::suites
