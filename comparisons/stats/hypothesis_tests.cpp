#include "comparisons/stats/hypothesis_tests.h"

#include "comparisons/stats/distributions.h"

#include <algorithm>
#include <cmath>

namespace tecido::stats {

bool Estimate::usable() const { return std::isfinite(value) && std::isfinite(se) && se > 0.0 && df > 0.0; }

Estimate mean_estimate(const Summary& s) {
  if (s.n < 2) return {};
  return {s.mean, s.se, static_cast<double>(s.n) - 1.0};
}

Estimate welch_estimate(const Summary& a, const Summary& b) {
  if (a.n < 2 || b.n < 2) return {};
  const double va = a.se * a.se, vb = b.se * b.se;
  const double df = (va + vb) * (va + vb) / (va * va / (a.n - 1.0) + vb * vb / (b.n - 1.0));
  return {a.mean - b.mean, std::sqrt(va + vb), df};
}

double p_above(const Estimate& e, double value) {
  if (!e.usable() || std::isnan(value)) return kNaN;
  return 1.0 - student_t_cdf((e.value - value) / e.se, e.df);
}

double p_below(const Estimate& e, double value) {
  if (!e.usable() || std::isnan(value)) return kNaN;
  return student_t_cdf((e.value - value) / e.se, e.df);
}

double p_two_sided(const Estimate& e, double value) {
  const double p = 2.0 * std::min(p_above(e, value), p_below(e, value));
  return std::isnan(p) ? kNaN : std::min(1.0, p);
}

Interval t_interval(const Estimate& e, double confidence) {
  if (!e.usable()) return kNoInterval;
  const double w = student_t_quantile(0.5 + 0.5 * confidence, e.df) * e.se;
  return {e.value - w, e.value + w};
}

Tost tost(const Estimate& e, double lo, double hi) {
  Tost t;
  if (!e.usable()) return t;
  t.p_lower = p_above(e, lo);
  t.p_upper = p_below(e, hi);
  t.p = std::max(t.p_lower, t.p_upper);
  t.p_outside = std::min(p_below(e, lo), p_above(e, hi));
  t.ci90 = t_interval(e, 0.90);
  return t;
}

double binomial_two_sided_p(int k, int n, double p0) {
  if (n < 1 || k < 0 || k > n) return kNaN;
  const double at_k = binomial_pmf(k, n, p0);
  if (std::isnan(at_k)) return kNaN;
  constexpr double relative_slack = 1.0 + 1e-7;  // R's binom.test: ties within rounding count as "as likely"
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double q = binomial_pmf(i, n, p0);
    if (q <= at_k * relative_slack) sum += q;
  }
  return std::min(1.0, sum);
}

double binomial_tost_p(int k, int n, double lo, double hi) {
  if (n < 1 || k < 0 || k > n) return kNaN;
  return std::max(binomial_upper_tail(k, n, lo), binomial_lower_tail(k, n, hi));
}

Interval wilson_interval(int k, int n, double confidence) {
  if (n < 1 || k < 0 || k > n || !(confidence > 0.0 && confidence < 1.0)) return kNoInterval;
  const double z = normal_quantile(0.5 + 0.5 * confidence);
  const double nn = n, p = k / nn, z2 = z * z;
  const double centre = (p + z2 / (2 * nn)) / (1 + z2 / nn);
  const double half = z / (1 + z2 / nn) * std::sqrt(p * (1 - p) / nn + z2 / (4 * nn * nn));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

}  // namespace tecido::stats
