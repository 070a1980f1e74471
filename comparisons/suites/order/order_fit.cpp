#include "comparisons/suites/order/order_fit.h"

#include <algorithm>

namespace tecido::suites {

OrderFit fit_order(const std::vector<double>& h, const std::vector<double>& e, double floor, double too_big,
                   double agree, int min_halvings) {
  OrderFit f;
  const int n = static_cast<int>(e.size());
  std::vector<bool> ok(n);
  for (int k = 0; k < n; ++k) {
    ok[k] = std::isfinite(e[k]) && e[k] < too_big && e[k] > floor;
    if (std::isfinite(e[k]) && e[k] <= floor && f.roundoff_below_h == 0.0) {
      // errors at and below this h are round-off
      f.roundoff_below_h = h[k];
    }
    if ((!std::isfinite(e[k]) || e[k] >= too_big)) f.unstable_above_h = std::max(f.unstable_above_h, h[k]);
  }
  f.observed.assign(std::max(0, n - 1), std::nan(""));
  for (int k = 0; k + 1 < n; ++k)
    if (ok[k] && ok[k + 1]) f.observed[k] = std::log2(e[k] / e[k + 1]);
  // Longest run of defined halvings whose orders agree step to step.
  int best_a = -1, best_b = -1;
  for (int a = 0; a + 1 < n; ++a) {
    if (!std::isfinite(f.observed[a])) continue;
    int b = a;
    while (b + 1 < n - 1 && std::isfinite(f.observed[b + 1]) && std::abs(f.observed[b + 1] - f.observed[b]) <= agree) ++b;
    if (b - a > best_b - best_a) {
      best_a = a;
      best_b = b;
    }
  }
  if (best_a < 0 || best_b - best_a + 1 < min_halvings) return f;
  f.first = best_a;
  f.last = best_b + 1;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const int m = f.last - f.first + 1;
  for (int k = f.first; k <= f.last; ++k) {
    const double x = std::log(h[k]), y = std::log(e[k]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  f.slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
  return f;
}

}  // namespace tecido::suites
