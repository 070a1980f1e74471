#pragma once
/// Tests on an estimate with a t distribution (one-sided, two-sided, equivalence by two one-sided
/// tests) and on a binomial count (two-sided exact, exact equivalence), with Wilson's interval.
/// Each p-value is NaN when it cannot be computed (no standard error, fewer than 2 values, or a
/// standard error of 0: data without variation, which no test can judge).
#include "comparisons/stats/summary.h"

#include <cstddef>

namespace tecido::stats {

/// An estimate whose (estimate - true value) / se follows Student's t with df degrees of freedom.
struct Estimate {
  double value = kNaN, se = kNaN, df = kNaN;
  /// se is finite and > 0 and df > 0: the tests below can use it.
  bool usable() const;
};
/// The mean of a sample (df = n - 1).
Estimate mean_estimate(const Summary& s);
/// mean(a) - mean(b) with Welch's standard error and Welch-Satterthwaite df (n_a, n_b >= 2).
Estimate welch_estimate(const Summary& a, const Summary& b);

/// One-sided p of H0: theta <= value against theta > value, and of H0: theta >= value against
/// theta < value; two-sided p of H0: theta = value.
double p_above(const Estimate& e, double value);
double p_below(const Estimate& e, double value);
double p_two_sided(const Estimate& e, double value);
/// The (1 - alpha) two-sided t interval of the estimate.
Interval t_interval(const Estimate& e, double confidence);

/// Two one-sided tests (Schuirmann 1987) of equivalence to the band [lo, hi]: p_lower tests
/// H0: theta <= lo, p_upper tests H0: theta >= hi; p = max of the two (equivalence at level alpha
/// when p < alpha, the same as the (1 - 2 alpha) interval lying inside the band). p_outside is
/// the evidence for the opposite, that theta lies wholly outside: the smaller of the one-sided p
/// of H0: theta >= lo (theta below the band) and of H0: theta <= hi (above it).
struct Tost {
  double p_lower = kNaN, p_upper = kNaN, p = kNaN, p_outside = kNaN;
  Interval ci90 = kNoInterval;  ///< the matching 90% interval
};
Tost tost(const Estimate& e, double lo, double hi);

/// Exact two-sided binomial test of H0: rate = p0 for k successes in n: the sum of P(X = i) over
/// every i no more likely than k (the "minimum likelihood" p-value of R's binom.test).
double binomial_two_sided_p(int k, int n, double p0);
/// Exact equivalence of a binomial rate to the band [lo, hi] (two one-sided exact tests): the larger
/// of P(X >= k | lo) and P(X <= k | hi).
double binomial_tost_p(int k, int n, double lo, double hi);

/// Wilson's score interval of a proportion k / n (n >= 1) at the given confidence.
Interval wilson_interval(int k, int n, double confidence = 0.95);

}  // namespace tecido::stats
