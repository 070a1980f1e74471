#pragma once
/// A continuous collision query rewritten as one system for both kinds: five difference
/// vectors of its points at t = 0 and t = 1, so that contact means
///   F(t, u, v) = Z(t) - u X(t) - v Y(t) = 0   for some t in [0, 1] and (u, v) in the domain,
/// every vector moving linearly in t:
///   vertex-face (x = p, a, b, c): X = b - a, Y = c - a, Z = p - a, P = b - p, Q = c - p;
///                                 domain u, v >= 0, u + v <= 1 (the point a + uX + vY of the face);
///   edge-edge (x = a0, a1, b0, b1): X = a1 - a0, Y = b0 - b1, Z = b0 - a0, P = a1 - b0,
///                                 Q = a0 - b1; domain u, v in [0, 1] (a0 + u X meets b0 + v (b1 - b0)).
/// P = X - Z and Q = Y - Z (the barycentric numerators of the third corner and of the far
/// ends of the edges) are computed from the points directly, so that every vector carries a
/// single rounding: each computed component is the true difference times (1 + d), |d| <= 2^-53.
/// Contact, time of impact and the barycentric coordinates are invariant under translation
/// and scaling, so the vectors are scaled by a power of two into [2^-128, 2^128] when needed
/// (exact, apart from underflow of points far smaller than the query, below 2^-1073 in
/// absolute terms after scaling, which the error bounds' absolute pads cover).
#include "core/geometry/ccd/query.h"

namespace tecido {

struct CcdSystem {
  enum Vector { X = 0, Y = 1, Z = 2, P = 3, Q = 4 };
  CcdKind kind = CcdKind::VertexFace;
  double d[2][5][3];  ///< d[time][vector][coordinate], after scaling
  double mag[3];      ///< per coordinate: the largest |component| of X, Y, Z at both times
  double vec_mag[3];  ///< per vector X, Y, Z: its largest |component| at both times
  double scale;       ///< max(mag): the query's scale L of CcdSettings
};

enum class CcdPrepared {
  Ok,           ///< the system is ready
  NonFinite,    ///< an input coordinate is NaN or infinite
  AllCoincide,  ///< every difference is zero: the points coincide at all times (contact at t = 0)
};

/// Fills s from q: the differences above, scaled by a power of two so that the largest
/// component lies in [2^-128, 2^128] (the underflow pads of the error bounds in
/// ccd/coplanarity_cubic.h, ccd/projected_quadratics.h and ccd/inclusion.h rely on it).
CcdPrepared prepare_ccd_system(const CcdQuery& q, CcdSystem& s);

}  // namespace tecido
