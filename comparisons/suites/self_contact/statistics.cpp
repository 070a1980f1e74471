#include "comparisons/suites/self_contact/statistics.h"

#include <cmath>
#include <limits>

namespace tecido::suites::self_contact {

namespace {
const Interval kNoInterval{kNaN, kNaN};
}  // namespace

Summary summarize(const std::vector<double>& xs) {
  Summary s;
  s.n = xs.size();
  if (s.n == 0) {
    s.mean = s.sd = s.se = kNaN;
    s.ci95 = s.pi95 = kNoInterval;
    return s;
  }
  double sum = 0.0;
  for (double x : xs) sum += x;
  s.mean = sum / static_cast<double>(s.n);
  if (s.n < 2) {
    s.sd = s.se = kNaN;
    s.ci95 = s.pi95 = kNoInterval;
    return s;
  }
  double ss = 0.0;
  for (double x : xs) ss += (x - s.mean) * (x - s.mean);
  const double n = static_cast<double>(s.n);
  s.sd = std::sqrt(ss / (n - 1.0));
  s.se = s.sd / std::sqrt(n);
  const double t = student_t_quantile(0.975, n - 1.0);
  s.ci95 = {s.mean - t * s.se, s.mean + t * s.se};
  const double w = t * s.sd * std::sqrt(1.0 + 1.0 / n);
  s.pi95 = {s.mean - w, s.mean + w};
  return s;
}

double log_gamma(double x) {
  static const double c[9] = {0.99999999999980993,  676.5203681218851,     -1259.1392167224028,
                              771.32342877765313,   -176.61502916214059,   12.507343278686905,
                              -0.13857109526572012, 9.9843695780195716e-6, 1.5056327351493116e-7};
  if (x < 0.5) return std::log(M_PI / std::sin(M_PI * x)) - log_gamma(1.0 - x);  // reflection
  x -= 1.0;
  double a = c[0];
  const double t = x + 7.5;
  for (int i = 1; i < 9; ++i) a += c[i] / (x + i);
  return 0.5 * std::log(2.0 * M_PI) + (x + 0.5) * std::log(t) - t + std::log(a);
}

namespace {
/// The continued fraction of I_x(a, b) (Numerical Recipes 3rd ed., betacf), modified Lentz.
double beta_fraction(double a, double b, double x) {
  constexpr double tiny = 1e-300, eps = 1e-15;
  const double qab = a + b, qap = a + 1.0, qam = a - 1.0;
  double c = 1.0, d = 1.0 - qab * x / qap;
  if (std::abs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 10000; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1.0 + aa * d;
    if (std::abs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1.0 + aa * d;
    if (std::abs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::abs(del - 1.0) < eps) break;
  }
  return h;
}
}  // namespace

double incomplete_beta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double front =
      std::exp(log_gamma(a + b) - log_gamma(a) - log_gamma(b) + a * std::log(x) + b * std::log1p(-x));
  // The fraction converges fast for x < (a + 1) / (a + b + 2); use the symmetry otherwise.
  if (x < (a + 1.0) / (a + b + 2.0)) return front * beta_fraction(a, b, x) / a;
  return 1.0 - front * beta_fraction(b, a, 1.0 - x) / b;
}

double student_t_cdf(double t, double df) {
  if (std::isnan(t) || !(df > 0.0)) return kNaN;
  const double tail = 0.5 * incomplete_beta(0.5 * df, 0.5, df / (df + t * t));  // P(T > |t|)
  return t >= 0.0 ? 1.0 - tail : tail;
}

double student_t_quantile(double p, double df) {
  if (!(p > 0.0 && p < 1.0) || !(df > 0.0)) return kNaN;
  if (p < 0.5) return -student_t_quantile(1.0 - p, df);
  double lo = 0.0, hi = 1.0;
  while (student_t_cdf(hi, df) < p && hi < 1e300) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (student_t_cdf(mid, df) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

Interval welch_ci95(double mean_a, double se_a, std::size_t n_a, double mean_b, double se_b, std::size_t n_b) {
  if (n_a < 2 || n_b < 2 || !std::isfinite(se_a) || !std::isfinite(se_b)) return kNoInterval;
  const double va = se_a * se_a, vb = se_b * se_b;
  const double d = mean_a - mean_b;
  if (va + vb == 0.0) return {d, d};
  const double df = (va + vb) * (va + vb) / (va * va / (n_a - 1.0) + vb * vb / (n_b - 1.0));
  const double t = student_t_quantile(0.975, df);
  const double w = t * std::sqrt(va + vb);
  return {d - w, d + w};
}

double binomial_upper_tail(int k, int n, double p) {
  if (n < 0 || n > 1000 || !(p >= 0.0 && p <= 1.0)) return kNaN;
  if (k <= 0) return 1.0;
  if (k > n) return 0.0;
  // pmf(i) = C(n, i) p^i (1-p)^(n-i), in logs so that no term under- or overflows early.
  double tail = 0.0;
  for (int i = k; i <= n; ++i) {
    const double log_c = log_gamma(n + 1.0) - log_gamma(i + 1.0) - log_gamma(n - i + 1.0);
    const double lp = (i > 0 ? i * std::log(p) : 0.0) + (n - i > 0 ? (n - i) * std::log1p(-p) : 0.0);
    tail += std::exp(log_c + lp);
  }
  return tail > 1.0 ? 1.0 : tail;
}

double sign_test_p(int k, int n) { return binomial_upper_tail(k, n, 0.5); }

Interval wilson_ci95(int k, int n) {
  if (n < 1 || k < 0 || k > n) return kNoInterval;
  constexpr double z = 1.959963984540054;  // the normal's 97.5% quantile
  const double nn = n, p = k / nn, z2 = z * z;
  const double centre = (p + z2 / (2 * nn)) / (1 + z2 / nn);
  const double half = z / (1 + z2 / nn) * std::sqrt(p * (1 - p) / nn + z2 / (4 * nn * nn));
  return {centre - half, centre + half};
}

double pearson(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = a.size();
  if (n < 2 || b.size() != n) return kNaN;
  double ma = 0.0, mb = 0.0;
  for (std::size_t i = 0; i < n; ++i) ma += a[i], mb += b[i];
  ma /= static_cast<double>(n);
  mb /= static_cast<double>(n);
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  if (!(saa > 0.0 && sbb > 0.0)) return kNaN;
  return sab / std::sqrt(saa * sbb);
}

double mid_percentile(const std::vector<double>& xs, double x) {
  if (xs.empty()) return kNaN;
  double below = 0.0;
  for (double v : xs) below += v < x ? 1.0 : (v == x ? 0.5 : 0.0);
  return below / static_cast<double>(xs.size());
}

}  // namespace tecido::suites::self_contact
