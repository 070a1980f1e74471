#include "core/geometry/plane_side.h"

#include "core/geometry/exact_dyadic.h"
#include "core/geometry/expansion_arithmetic.h"

#include <cmath>

#if defined(__FAST_MATH__)
#error "plane_side_sign's filter relies on IEEE-754 rounding: do not build it with -ffast-math"
#endif

namespace tecido::detail {
namespace {

/// 0 or of magnitude in [2^-450, 2^450]: every input is then a multiple of 2^-502, so is each
/// difference p_k - P_k (below 2^451), and each product of a normal component and a
/// difference, with its two_product low part, a multiple of 2^-1004 below 2^902: expansion
/// arithmetic on them neither underflows nor overflows, so it is exact.
bool tame(double v) {
  const double a = std::fabs(v);
  return a == 0.0 || (a >= 0x1p-450 && a <= 0x1p450);
}

bool tame(const Vec3& v) { return tame(v.x()) && tame(v.y()) && tame(v.z()); }

}  // namespace

int plane_side_sign_exact(const BoundedPlane& plane, const Vec3& p) {
  if (!p.allFinite() || !plane.position.allFinite() || !plane.normal.allFinite()) {
    const double s = plane.normal.dot(p - plane.position);
    return (s > 0.0) - (s < 0.0);
  }
  if (tame(p) && tame(plane.position) && tame(plane.normal)) {
    // s = sum_k n_k (p_k - P_k) as an exact expansion (Shewchuk 1997): each difference as a
    // two-term expansion, scaled by n_k, the three summed.
    double term[3][4];
    int len[3];
    for (int k = 0; k < 3; ++k) {
      double d[2];
      const int dn = expansion::diff_expansion(p[k], plane.position[k], d);
      len[k] = expansion::scale_expansion(dn, d, plane.normal[k], term[k]);
    }
    double s01[8], s[12];
    const int n01 = expansion::sum_expansion(len[0], term[0], len[1], term[1], s01);
    const int n = expansion::sum_expansion(n01, s01, len[2], term[2], s);
    return expansion::expansion_sign(n, s);
  }
  // Any finite input: exact dyadic arithmetic.
  Dyadic s;
  for (int k = 0; k < 3; ++k) s = s + Dyadic(plane.normal[k]) * (Dyadic(p[k]) - Dyadic(plane.position[k]));
  return s.sign();
}

}  // namespace tecido::detail
