#pragma once
/// The coplanarity cubic of a continuous collision query: f(t) = det(X(t), Y(t), Z(t)), six
/// times the signed volume of the tetrahedron of the query's four points at time t
/// (ccd/system.h for X, Y, Z). Contact at time t needs the four points coplanar, f(t) = 0
/// (a vertex in a triangle, or two crossing segments, lie in one plane); so a cubic that is
/// certainly nonzero on an interval rules out contact there. The classical first step of
/// continuous collision detection (Provot 1997, "Collision and self-collision handling in
/// cloth model dedicated to design garments"; Bridson, Fedkiw and Anderson 2002), here in
/// Bernstein form with a rigorous error bound instead of a floating-point root finder.
#include "core/geometry/ccd/bernstein.h"
#include "core/geometry/ccd/system.h"

namespace tecido {

/// Bernstein coefficients of f on [0, 1] (into f[0..3]) and a bound `err` such that each is
/// within err.e0 of the true coefficient of the query the system describes; err.step is set
/// for halving (ccd/bernstein.h).
///
/// With C_ij = Y_i x Z_j and S = C_10 + C_01: b0 = X0.C00, b1 = (X1.C00 + X0.S) / 3,
/// b2 = (X0.C11 + X1.S) / 3, b3 = X1.C11 (the product of X's degree-1 and (Y x Z)'s degree-2
/// Bernstein forms). Error: every elementary product x y z of a coefficient passes through at
/// most 11 roundings (3 in the differences X, Y, Z, then multiply, subtract, add for S,
/// multiply, two dot-product adds, one add, the division by 3), so the error is at most
/// gamma_11 = 11 eps / (1 - 11 eps) times the coefficient's permanent (the same sum with every
/// term replaced by its absolute value), computed alongside; 16 eps times the computed
/// permanent covers gamma_11 and the permanent's own rounding. Underflowing products add at
/// most 2^-1075 each, times a third factor below 2^129 (ccd/system.h's scaling): 2^-900 in
/// all is far more. A cheaper bound, 6 mx my mz for the permanent (mx the largest component of
/// X over both times, likewise my, mz), is tried first and kept when it already certifies the
/// cubic's sign on [0, 1].
void ccd_coplanarity_cubic(const CcdSystem& s, double f[4], CcdErrorBound& err);

}  // namespace tecido
