#pragma once
/// The `tradeoff` suite's formulas: the springs' highest frequency and the step sweep it sets, and
/// the step-halving (Richardson) estimate of the reference's own error with the observed order
/// that justifies it.
#include "core/scene/scene.h"

#include <vector>

namespace tecido::suites::tradeoff {

/// Upper bound on the highest angular frequency of the scene's springs about rest (Gershgorin on
/// M^-1 K: max over nodes of sqrt(inv_mass sum 2 ks)) [1/s].
double omega_bound(const Scene& scene);

/// The sweep's first step: h0 = 2^ceil(log2(2 / omega_bound)), the power of two at or above
/// symplectic Euler's stability limit 2 / omega [s].
double first_step(const Scene& scene);

/// h0, h0/2, ..., `count` steps [s].
std::vector<double> swept_steps(const Scene& scene, int count);

/// The own error of a run of a method of order p at step h, estimated from `diff`, its distance to
/// the same method at 2h: e(h) ~ diff / (2^p - 1) (step halving, Richardson).
double richardson_error(double diff, double order);

/// log2(e(h) / e(h/2)): the observed order of two errors at halving steps.
double observed_order(double error_h, double error_half_h);

}  // namespace tecido::suites::tradeoff
