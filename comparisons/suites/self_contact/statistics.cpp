#include "comparisons/suites/self_contact/statistics.h"

#include <cmath>

namespace tecido::suites::self_contact {

Interval welch_ci95(double mean_a, double se_a, std::size_t n_a, double mean_b, double se_b, std::size_t n_b) {
  if (n_a < 2 || n_b < 2 || !std::isfinite(se_a) || !std::isfinite(se_b)) return stats::kNoInterval;
  Summary a, b;
  a.n = n_a, a.mean = mean_a, a.se = se_a;
  b.n = n_b, b.mean = mean_b, b.se = se_b;
  const stats::Estimate d = stats::welch_estimate(a, b);
  if (d.se == 0.0) return {d.value, d.value};
  return stats::t_interval(d, 0.95);
}

double sign_test_p(int k, int n) { return stats::binomial_upper_tail(k, n, 0.5); }

Interval wilson_ci95(int k, int n) { return stats::wilson_interval(k, n, 0.95); }

double mid_percentile(const std::vector<double>& xs, double x) {
  if (xs.empty()) return kNaN;
  double below = 0.0;
  for (double v : xs) below += v < x ? 1.0 : (v == x ? 0.5 : 0.0);
  return below / static_cast<double>(xs.size());
}

}  // namespace tecido::suites::self_contact
