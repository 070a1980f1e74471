#include "core/geometry/ccd/coplanarity_cubic.h"

#include "core/geometry/ccd/decisions.h"

#include <algorithm>
#include <cmath>

namespace tecido {

void ccd_coplanarity_cubic(const CcdSystem& s, double f[4], CcdErrorBound& err) {
  using namespace ccd_scalar;
  const V3<Lanes> x0 = v3(s.d[0][CcdSystem::X]), x1 = v3(s.d[1][CcdSystem::X]);
  const V3<Lanes> y0 = v3(s.d[0][CcdSystem::Y]), y1 = v3(s.d[1][CcdSystem::Y]);
  const V3<Lanes> z0 = v3(s.d[0][CcdSystem::Z]), z1 = v3(s.d[1][CcdSystem::Z]);
  cubic_coefficients<Lanes>(x0, x1, y0, y1, z0, z1, f);
  // First a cheap bound: every coefficient is an average of determinants whose six terms are
  // each at most mx my mz (the largest components of X, Y, Z over both times), so the
  // permanent is at most 6 mx my mz. When the coefficients clear it, that bound certifies the
  // cubic's sign; otherwise (near-coplanar motion) the permanents themselves are computed.
  const double* m = s.vec_mag;  // the largest components of X, Y, Z over both times
  err.e0 = cubic_cheap_bound<Lanes>(m[0], m[1], m[2]);
  const double lo = std::min(std::min(f[0], f[1]), std::min(f[2], f[3]));
  const double hi = std::max(std::max(f[0], f[1]), std::max(f[2], f[3]));
  if (!(lo > err.e0 || hi < -err.e0)) err.e0 = cubic_permanent_bound<Lanes>(x0, x1, y0, y1, z0, z1);
  err.step = bound_step<Lanes>(largest_abs<Lanes>(f, 4), err.e0);
}

}  // namespace tecido
