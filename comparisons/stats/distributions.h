#pragma once
/// The distribution functions the tests need: ln Gamma, the regularized incomplete beta, Student's
/// t (cdf and quantile, real degrees of freedom), the standard normal, and the binomial's pmf and
/// tails. Plain formulas from the references named beside each; no third-party library.
namespace tecido::stats {

/// ln Gamma(x) for x > 0 (Lanczos, g = 7, 9 terms; relative error ~1e-15).
double log_gamma(double x);
/// The regularized incomplete beta function I_x(a, b), a, b > 0, x in [0, 1] (continued
/// fraction by the modified Lentz method; Press et al., Numerical Recipes, 3rd ed., 6.4).
double incomplete_beta(double a, double b, double x);
/// P(T <= t) for Student's t with df > 0 degrees of freedom (real df allowed, for Welch).
double student_t_cdf(double t, double df);
/// The quantile t with P(T <= t) = p, p in (0, 1) (bisection on the cdf to 1e-12 relative).
double student_t_quantile(double p, double df);
/// The standard normal's cdf (erfc) and quantile (bisection on the cdf to 1e-14).
double normal_cdf(double z);
double normal_quantile(double p);

/// P(X = k), P(X <= k) and P(X >= k) for X ~ Binomial(n, p), 0 <= n <= 100000, sums of pmfs
/// computed in logs; NaN for p outside [0, 1] or n out of range.
double binomial_pmf(int k, int n, double p);
double binomial_lower_tail(int k, int n, double p);
double binomial_upper_tail(int k, int n, double p);

}  // namespace tecido::stats
