#pragma once
/// The root of a cubic in Bernstein form on [0, 1] whose end values differ in sign: an
/// approximation only, which the caller certifies (ccd/time_search.cpp brackets it and checks
/// the bracket's end values with rigorous error bounds).

namespace tecido {

/// A root in [0, 1] of p(s) = sum_i b_i B_i^3(s), given b[0] and b[3] nonzero of opposite
/// signs, to about tol: safeguarded Newton (regula falsi start, a bisection step whenever the
/// Newton step leaves the bracket of a sign change; Press et al., Numerical Recipes,
/// "rtsafe"), on the power form by Horner's rule. Converges quadratically when p is monotone.
/// Stops when a step is within tol, when the bracket is, or when after a Newton step d the
/// predicted error of the new iterate, |p''| d^2 / (2 |p'|), is at most tol / 2 (which saves
/// the last, confirming step, about one of five). Only a speed matter: the caller certifies
/// whatever comes back (tests/core/geometry/ccd/test_cubic_root.cpp checks the accuracy).
double ccd_cubic_root(const double b[4], double tol);

}  // namespace tecido
