#include "core/geometry/ccd_cubic_root.h"

#include <cmath>

namespace tecido {

double ccd_cubic_root(const double b[4], double tol) {
  // Power basis (Horner is cheaper than de Casteljau; the result is only an approximation).
  const double c0 = b[0], c1 = 3.0 * (b[1] - b[0]), c2 = 3.0 * (b[2] - 2.0 * b[1] + b[0]);
  const double c3 = b[3] - 3.0 * b[2] + 3.0 * b[1] - b[0];
  const bool rising = b[0] < 0.0;  // p < 0 left of the root
  double lo = 0.0, hi = 1.0;
  double s = b[0] / (b[0] - b[3]);
  if (!(s > 0.0 && s < 1.0)) s = 0.5;
  for (int it = 0; it < 64; ++it) {
    const double p = ((c3 * s + c2) * s + c1) * s + c0;
    const double dp = (3.0 * c3 * s + 2.0 * c2) * s + c1;
    if (p == 0.0) return s;
    if ((p < 0.0) == rising) {
      lo = s;
    } else {
      hi = s;
    }
    double next = s - p / dp;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - s) <= tol || hi - lo <= tol) return next;
    s = next;
  }
  return s;
}

}  // namespace tecido
