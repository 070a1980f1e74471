#pragma once
/// The calibrated kLST of the registry's classic soft body (bullet_dynamics_engines.h): the
/// classic body's links are constraints, not springs, so kLST is calibrated per scene, step and
/// number of sweeps so that the static sag matches core's (reference/klst_calibration.h).
#include "comparisons/engines/classic_calibration.h"
#include "core/scene/scene.h"

namespace tecido::engines {

/// The calibrated kLST the classic engine uses for `scene` at step h with `piterations` sweeps:
/// calibrate_klst_for_sag (reference/klst_calibration.h) with the settling and stopping rules of
/// `c`, the secant started from klst_scaling_guess; computed once per (scene, h, piterations,
/// calibration settings) and cached behind a mutex, keyed by a hash of everything it reads. The
/// value is a pure function of its arguments, whatever the order or threads of the calls
/// (concurrent first calls of one key wait for a single computation). Throws what the
/// calibration throws (an engine unstable while settling), every time for that key.
double classic_klst(const Scene& scene, double h, int piterations, const ClassicCalibration& c);

}  // namespace tecido::engines
