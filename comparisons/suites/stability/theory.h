#pragma once
/// The `stability` suite's theory: linear stability of the integrators on x'' = -omega^2 x, written
/// with c = h omega, and the predictions the suite measures against. The amplification factors are
/// the standard ones of each method applied to the test equation y' = i omega y (explicit Euler
/// R = 1 + z, midpoint R = 1 + z + z^2/2, RK4 the degree-4 Taylor polynomial of e^z, z = ic);
/// symplectic Euler's update of (x, v/omega) is the matrix [[1 - c^2, c], [-c, 1]].
#include "core/dynamics/integrator.h"

namespace tecido::suites::stability {

constexpr double kPi = 3.14159265358979323846;

/// |R(ic)|: the factor by which one step multiplies the norm of (x, v/omega) (euler, midpoint, rk4:
/// their update is a scaled rotation). For symplectic Euler, whose update is not normal, the
/// spectral radius: 1 for c <= 2, (b + sqrt(b^2 - 4))/2 with b = c^2 - 2 above.
double amplification(IntegratorKind k, double c);

/// The largest c = h omega with |R(ic)| <= 1: 2 for symplectic Euler (trace 2 - c^2, determinant
/// 1), 2 sqrt 2 for RK4 (|R|^2 = 1 - c^6/72 + c^8/576); NaN for explicit Euler and midpoint, which
/// amplify at every c > 0.
double stable_limit(IntegratorKind k);

/// |R(ic)|^(2 pi / c): the growth of the norm over one period of the exact motion.
double growth_per_period(IntegratorKind k, double c);

/// The c at which a run of `periods` periods grows by exactly `bound`: the root of
/// (2 pi N / c) ln|R(ic)| = ln bound on (0, 2), by bisection. It is the largest step a run of N
/// periods calls stable for a method whose amplification exceeds 1 at every c (euler, midpoint):
/// about ln(bound) / (pi N) for Euler and (4 ln(bound) / (pi N))^(1/3) for midpoint.
double horizon_prediction(IntegratorKind k, double periods, double bound);

/// Symplectic Euler's measured limit under an amplitude bound: near c = 2 its invariant ellipse
/// stretches, so released at rest |x| peaks at 2 / sqrt(4 - c^2) times the initial amplitude; a
/// bound of B stops it at c = 2 sqrt(1 - 1/B^2).
double bound_stretch_limit(double bound);

/// omega_max of two free particles m1, m2 joined by a spring ks: sqrt(ks (1/m1 + 1/m2)).
double pair_omega_max(double ks, double m1, double m2);
/// omega_max of the chain anchor - m1 - m2 (two springs ks): the larger root of the eigenvalues of
/// M^-1 K, K = ks [[2, -1], [-1, 1]].
double chain_omega_max(double ks, double m1, double m2);

/// The spacing of doubles at x: nextafter(x, +inf) - x.
double ulp_of(double x);
/// The smallest separation d whose square is not rounded to 0: sqrt(denorm_min) / sqrt 2 (below it
/// |d| = sqrt(|d|^2) is 0 in floating point).
double underflow_separation();

}  // namespace tecido::suites::stability
