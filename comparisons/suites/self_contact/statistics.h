#pragma once
/// The statistics of the self-contact experiment: summaries of an ensemble of runs, Student t
/// intervals, Welch's difference of two means, the sign test, and a correlation. Plain formulas
/// from the textbooks named beside each; no third-party library.
#include <cstddef>
#include <limits>
#include <vector>

namespace tecido::suites::self_contact {

/// A value that is not there (no runs, no seed value, no interval): NaN.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// An interval [lo, hi]; NaN ends when it cannot be computed.
struct Interval {
  double lo = 0.0, hi = 0.0;
  bool contains(double x) const { return lo <= x && x <= hi; }
  bool below(double x) const { return hi < x; }  ///< every point < x
  bool above(double x) const { return lo > x; }  ///< every point > x
};

/// Mean, sample standard deviation (n - 1), the 95% t interval of the mean and the 95%
/// prediction interval of one more draw (mean +- t sd sqrt(1 + 1/n)); n < 2 gives NaN spreads.
struct Summary {
  std::size_t n = 0;
  double mean = 0.0, sd = 0.0, se = 0.0;
  Interval ci95, pi95;
};
Summary summarize(const std::vector<double>& xs);

/// ln Gamma(x) for x > 0 (Lanczos, g = 7, 9 terms; relative error ~1e-15).
double log_gamma(double x);
/// The regularized incomplete beta function I_x(a, b), a, b > 0, x in [0, 1] (continued
/// fraction by the modified Lentz method; Press et al., Numerical Recipes, 3rd ed., 6.4).
double incomplete_beta(double a, double b, double x);
/// P(T <= t) for Student's t with df > 0 degrees of freedom (real df allowed, for Welch).
double student_t_cdf(double t, double df);
/// The quantile t with P(T <= t) = p, p in (0, 1) (bisection on the cdf to 1e-12 relative).
double student_t_quantile(double p, double df);

/// Welch's 95% interval of mean(a) - mean(b) from two summaries (standard errors se_a, se_b,
/// sample sizes n_a, n_b >= 2), df by Welch-Satterthwaite. NaN when it cannot be computed.
Interval welch_ci95(double mean_a, double se_a, std::size_t n_a, double mean_b, double se_b, std::size_t n_b);

/// One-sided sign test: P(X >= k) for X ~ Binomial(n, 1/2) (exact sum; n <= 1000).
double sign_test_p(int k, int n);
/// Upper binomial tail P(X >= k) for X ~ Binomial(n, p) (exact sum; n <= 1000).
double binomial_upper_tail(int k, int n, double p);

/// Wilson's 95% score interval of a proportion k / n (n >= 1).
Interval wilson_ci95(int k, int n);

/// Pearson's correlation of paired samples; NaN for fewer than 2 pairs or no spread.
double pearson(const std::vector<double>& a, const std::vector<double>& b);

/// Where x falls in the sample: (#{x_i < x} + #{x_i == x} / 2) / n (the mid-rank percentile);
/// NaN for an empty sample.
double mid_percentile(const std::vector<double>& xs, double x);

}  // namespace tecido::suites::self_contact
