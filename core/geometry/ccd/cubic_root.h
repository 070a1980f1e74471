#pragma once
/// The root of a cubic in Bernstein form on [0, 1] whose end values differ in sign: an
/// approximation only, which the caller certifies (ccd/time_search.cpp brackets it and checks
/// the bracket's end values with rigorous error bounds).

namespace tecido {

/// A root in [0, 1] of p(s) = sum_i b_i B_i^3(s), given b[0] and b[3] nonzero of opposite
/// signs, to about tol: safeguarded Newton (regula falsi start, a bisection step whenever the
/// Newton step leaves the bracket of a sign change; Press et al., Numerical Recipes,
/// "rtsafe"), on the power form by Horner's rule. Converges quadratically when p is monotone.
double ccd_cubic_root(const double b[4], double tol);

}  // namespace tecido
