#include "core/geometry/ccd_cubic_root.h"

#include <cmath>

namespace tecido {

double ccd_cubic_root(const double b[4]) {
  auto lerp = [](double x, double y, double s) { return (1.0 - s) * x + s * y; };
  const bool rising = b[0] < 0.0;  // p < 0 left of the root
  double lo = 0.0, hi = 1.0;
  double s = b[0] / (b[0] - b[3]);
  if (!(s > 0.0 && s < 1.0)) s = 0.5;
  for (int it = 0; it < 60; ++it) {
    const double l0 = lerp(b[0], b[1], s), l1 = lerp(b[1], b[2], s), l2 = lerp(b[2], b[3], s);
    const double m0 = lerp(l0, l1, s), m1 = lerp(l1, l2, s);
    const double p = lerp(m0, m1, s), dp = 3.0 * (m1 - m0);
    if (p == 0.0) return s;
    if ((p < 0.0) == rising) {
      lo = s;
    } else {
      hi = s;
    }
    double next = s - p / dp;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - s) <= 0x1p-52 || hi - lo <= 0x1p-52) return next;
    s = next;
  }
  return s;
}

}  // namespace tecido
